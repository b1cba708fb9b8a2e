"""Numbers read and written as Java reads and writes them, so that this reader and the Java one agree."""
from __future__ import annotations

import math
import re
from decimal import ROUND_HALF_UP, Decimal
from typing import Optional

_DECIMAL = re.compile(r"([+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)[fFdD]?")
_HEX = re.compile(r"([+-]?)0[xX]((?:[0-9a-fA-F]+\.?[0-9a-fA-F]*|\.[0-9a-fA-F]+)[pP][+-]?\d+)[fFdD]?")
_SPECIAL = re.compile(r"([+-]?)(NaN|Infinity)")


def java_trim(text: str) -> str:
    """String.trim: off both ends, every character up to the space."""
    start, end = 0, len(text)
    while start < end and text[start] <= " ":
        start += 1
    while end > start and text[end - 1] <= " ":
        end -= 1
    return text[start:end]


def java_double(text: str) -> Optional[float]:
    """Double.parseDouble, or None where it throws."""
    text = java_trim(text)
    found = _DECIMAL.fullmatch(text)
    if found:
        return float(found.group(1))
    found = _HEX.fullmatch(text)
    if found:
        value = float.fromhex("0x" + found.group(2))
        return -value if found.group(1) == "-" else value
    found = _SPECIAL.fullmatch(text)
    if found:
        value = math.nan if found.group(2) == "NaN" else math.inf
        return -value if found.group(1) == "-" else value
    return None


def _decimal(value: float) -> Decimal:
    # The shortest digits that read back as the value, as Java's Formatter starts from.
    return Decimal(repr(value))


def java_f(value: float, places: int) -> str:
    """String.format(Locale.ROOT, "%.Nf", value): rounded half up."""
    if not math.isfinite(value):
        return "NaN" if math.isnan(value) else ("Infinity" if value > 0 else "-Infinity")
    return format(_decimal(value).quantize(Decimal(1).scaleb(-places), ROUND_HALF_UP), "f")


def java_g(value: float, precision: int) -> str:
    """String.format(Locale.ROOT, "%.Ng", value): N significant digits rounded half up, trailing zeros kept."""
    if not math.isfinite(value):
        return "NaN" if math.isnan(value) else ("Infinity" if value > 0 else "-Infinity")
    d = _decimal(value)
    if d.is_zero():
        return format(d.quantize(Decimal(1).scaleb(1 - precision)), "f")
    exponent = d.adjusted()
    rounded = d.quantize(Decimal(1).scaleb(exponent - precision + 1), ROUND_HALF_UP)
    if rounded.adjusted() != exponent:  # 9.9996 became 10.00
        exponent = rounded.adjusted()
        rounded = d.quantize(Decimal(1).scaleb(exponent - precision + 1), ROUND_HALF_UP)
    if -4 <= exponent < precision:
        return format(rounded, "f")
    mantissa = format(rounded.scaleb(-exponent), "f")
    return f"{mantissa}e{'-' if exponent < 0 else '+'}{abs(exponent):02d}"


def java_string(value: float) -> str:
    """Double.toString: plain from 0.001 up to 10 million, else d.dddE-n; at least one digit after the point."""
    if not math.isfinite(value):
        return "NaN" if math.isnan(value) else ("Infinity" if value > 0 else "-Infinity")
    if value == 0:
        return "-0.0" if math.copysign(1.0, value) < 0 else "0.0"
    d = _decimal(value)
    if 1e-3 <= abs(value) < 1e7:
        text = format(d, "f")
        return text if "." in text else text + ".0"
    exponent = d.adjusted()
    mantissa = format(d.scaleb(-exponent).normalize(), "f")
    if "." not in mantissa:
        mantissa += ".0"
    return f"{mantissa}E{exponent}"
