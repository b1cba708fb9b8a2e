package io.orchard.protocol.value;

import com.fasterxml.jackson.annotation.JsonValue;

/**
 * The eight compass sectors in which the castle is perceived, "rather vaguely" as the paper says.
 * North is {@code -z}, east is {@code +x}; each sector spans 45 degrees around its direction.
 */
public enum Sector {
    /** Towards -z. */
    NORTH("north"),

    /** Between north and east. */
    NORTH_EAST("north-east"),

    /** Towards +x. */
    EAST("east"),

    /** Between south and east. */
    SOUTH_EAST("south-east"),

    /** Towards +z. */
    SOUTH("south"),

    /** Between south and west. */
    SOUTH_WEST("south-west"),

    /** Towards -x. */
    WEST("west"),

    /** Between north and west. */
    NORTH_WEST("north-west");

    private final String wireName;

    Sector(String wireName) {
        this.wireName = wireName;
    }

    /**
     * The sector of the direction from one ground point to another.
     *
     * @param dx east-west difference (target minus origin)
     * @param dz north-south difference (target minus origin)
     */
    public static Sector of(double dx, double dz) {
        double compass = Math.toDegrees(Math.atan2(dx, -dz)); // 0 = north, 90 = east
        int index = (int) Math.floorMod(Math.round(compass / 45.0), 8L);
        return values()[index];
    }

    /** The name of this value on the wire. */
    @JsonValue
    public String wireName() {
        return wireName;
    }
}
