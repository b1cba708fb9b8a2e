package io.orchard.protocol.value;

/**
 * The units of the lean perception ({@code LeanPerception}): lengths in whole centimetres and angles
 * in whole milliradians, the precision to which the server rounds what an agent perceives. The
 * conversions here are the only ones: the server writes with them and clients read back with them,
 * so a number that went through both is the number the ordinary form carries.
 *
 * <p>One angle is special: the server rounds a bearing of almost π to π itself, which is 3142
 * milliradians; {@link #radians(long)} reads 3142 back as {@link Math#PI}, so that a bearing stays
 * in (-π, π].
 */
public final class LeanUnits {

    /** π in whole milliradians, as the lean form writes it. */
    public static final long PI_MILLIRADIANS = 3142;

    private LeanUnits() {}

    /**
     * A length in whole centimetres, rounded half up.
     *
     * @throws IllegalArgumentException when it is not finite or does not fit in an int
     */
    public static int centimetres(double units) {
        double scaled = Math.round(units * 100);
        if (!Double.isFinite(units) || scaled > Integer.MAX_VALUE || scaled < Integer.MIN_VALUE) {
            throw new IllegalArgumentException("a length must be finite and within ±21,474,836 units to be written"
                    + " in centimetres, was " + units);
        }
        return (int) scaled;
    }

    /**
     * The size of a thing (a radius, a height, a width) in whole centimetres: at least 1, since a
     * thing has a size greater than 0 however small it is.
     */
    public static int size(double units) {
        return Math.max(1, centimetres(units));
    }

    /**
     * An angle in whole milliradians, rounded half up.
     *
     * @throws IllegalArgumentException when it is not finite
     */
    public static long milliradians(double radians) {
        if (!Double.isFinite(radians)) {
            throw new IllegalArgumentException("an angle must be finite to be written in milliradians, was " + radians);
        }
        return Math.round(radians * 1000);
    }

    /** A length in units from whole centimetres. */
    public static double units(int centimetres) {
        return centimetres / 100.0;
    }

    /** An angle in radians from whole milliradians; {@link #PI_MILLIRADIANS} is π itself. */
    public static double radians(long milliradians) {
        return milliradians == PI_MILLIRADIANS ? Math.PI : milliradians / 1000.0;
    }

    /** A bearing in milliradians is one of (-π, π]: -3141 to 3142. */
    static int bearing(int milliradians, String field) {
        if (milliradians <= -PI_MILLIRADIANS || milliradians > PI_MILLIRADIANS) {
            throw new IllegalArgumentException(field + " must be a bearing in milliradians from -3141 to 3142, was "
                    + milliradians);
        }
        return milliradians;
    }

    /** A distance in centimetres is 0 or more. */
    static int distance(int centimetres, String field) {
        if (centimetres < 0) {
            throw new IllegalArgumentException(field + " must not be negative, was " + centimetres);
        }
        return centimetres;
    }

    /** A size in centimetres is 1 or more. */
    static int size(int centimetres, String field) {
        if (centimetres < 1) {
            throw new IllegalArgumentException(field + " must be at least 1 (centimetre), was " + centimetres);
        }
        return centimetres;
    }

    /** A relative position from centimetres and milliradians. */
    static RelativePosition relative(int distance, int bearing) {
        return new RelativePosition(units(distance), radians(bearing));
    }
}
