package io.orchard.protocol.value;

/**
 * What an agent can perceive: objects within {@code range} units and within {@code fieldOfView}
 * radians centred on its heading (so {@code Math.PI} sees a half circle ahead).
 *
 * @param range       perception range in units
 * @param fieldOfView the full opening angle of the view cone, in radians, at most 2&pi;
 */
public record Sight(double range, double fieldOfView) {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public Sight {
        Checks.positive(range, "range");
        Checks.positive(fieldOfView, "fieldOfView");
        if (fieldOfView > 2 * Math.PI) {
            throw new IllegalArgumentException("fieldOfView must be at most 2*pi radians, was " + fieldOfView);
        }
    }
}
