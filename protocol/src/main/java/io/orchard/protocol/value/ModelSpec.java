package io.orchard.protocol.value;

import java.util.Base64;
import java.util.List;

/**
 * An agent's visual model, sent at registration so that viewers show the agent as its author
 * designed it: either the model's bytes ({@code data}, Base64) in one of the model formats, or the
 * name of a model the viewer ships ({@code format} {@link ModelFormat#BUNDLED} and {@code bundled}).
 *
 * @param format  the model's format
 * @param bundled the name of a bundled model, only with {@link ModelFormat#BUNDLED}: one of
 *                {@link #BUNDLED_NAMES}, which the server checks when an agent registers
 * @param data    the model file, Base64-encoded (standard alphabet, with padding); at most
 *                {@link #MAX_MODEL_BYTES} once decoded; with {@link ModelFormat#ZIP} a zip whose
 *                files also unpack to at most that ({@link ModelArchive}, which the server checks
 *                when an agent registers)
 * @param fit     how viewers size and place the model (version 2); absent means
 *                {@link ModelFit#BODY}
 */
public record ModelSpec(ModelFormat format, @Nullable String bundled, @Nullable String data, @Nullable ModelFit fit) {

    /**
     * The models a viewer ships, by the name a {@code bundled} spec gives: an agent that names one
     * is drawn as that model. The server refuses a registration that names any other.
     */
    public static final List<String> BUNDLED_NAMES = List.of("figure", "bunny");

    /** The largest model, in bytes before Base64 encoding: 4 MiB. */
    public static final int MAX_MODEL_BYTES = 4 * 1024 * 1024;

    /** Checks the components; a bad value is refused with an exception that names it. */
    public ModelSpec {
        Checks.present(format, "format");
        if (format == ModelFormat.BUNDLED) {
            Checks.name(bundled, "bundled");
            if (data != null) {
                throw new IllegalArgumentException("data must be absent for a bundled model");
            }
        } else {
            Checks.present(data, "data");
            if (bundled != null) {
                throw new IllegalArgumentException("bundled is only for format 'bundled', was " + Checks.quote(bundled));
            }
            if (data.length() > (MAX_MODEL_BYTES + 2) / 3 * 4) {
                throw new IllegalArgumentException("data must decode to at most " + MAX_MODEL_BYTES
                        + " bytes, its Base64 text has " + data.length() + " characters");
            }
            int size;
            try {
                size = Base64.getDecoder().decode(data).length;
            } catch (IllegalArgumentException e) {
                throw new IllegalArgumentException("data must be Base64 (the standard alphabet A-Z, a-z, 0-9, '+', '/',"
                        + " with '=' padding), " + notBase64(data));
            }
            // The length test above lets through up to two bytes more than the limit: count exactly.
            if (size > MAX_MODEL_BYTES) {
                throw new IllegalArgumentException("data must decode to at most " + MAX_MODEL_BYTES
                        + " bytes, it decodes to " + size);
            }
        }
    }

    /** What is wrong with text that does not decode as Base64, naming the first bad character or the length. */
    private static String notBase64(String data) {
        int padding = data.indexOf('=');
        for (int i = 0; i < data.length(); i++) {
            char c = data.charAt(i);
            boolean alphabet = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '+'
                    || c == '/';
            if (!alphabet && c != '=' || c != '=' && padding >= 0 && i > padding) {
                return "has " + (c >= 0x20 && c < 0x7f ? "'" + c + "'" : String.format(java.util.Locale.ROOT,
                        "U+%04X", (int) c)) + " at character " + i;
            }
        }
        return "its " + data.length() + " characters do not make whole groups of 4 (with padding)";
    }

    /** A spec fitted to the body, as every version 1 spec is. */
    public ModelSpec(ModelFormat format, @Nullable String bundled, @Nullable String data) {
        this(format, bundled, data, null);
    }

    /** This spec with another {@code fit}; {@link ModelFit#BODY} is written as absent. */
    public ModelSpec withFit(ModelFit value) {
        return new ModelSpec(format, bundled, data, value == ModelFit.BODY ? null : value);
    }

    /** How viewers size and place the model: {@code fit}, or {@link ModelFit#BODY} when absent. */
    public ModelFit fitOrDefault() {
        return fit == null ? ModelFit.BODY : fit;
    }

    /**
     * This spec as a client of protocol version 1 is sent it: without {@code fit}, and nothing (the
     * agent shows as a placeholder) for a format version 1 does not know.
     */
    public @Nullable ModelSpec forVersion1() {
        if (!format.inVersion1()) {
            return null;
        }
        return fit == null ? this : new ModelSpec(format, bundled, data);
    }

    /** A model given by its bytes. */
    public static ModelSpec of(ModelFormat format, byte[] bytes) {
        return new ModelSpec(format, null, Base64.getEncoder().encodeToString(bytes));
    }

    /** One of the viewer's bundled models, by name. */
    public static ModelSpec bundled(String name) {
        return new ModelSpec(ModelFormat.BUNDLED, name, null);
    }

    /** The model's bytes; empty for a bundled model. */
    public byte[] bytes() {
        return data == null ? new byte[0] : Base64.getDecoder().decode(data);
    }
}
