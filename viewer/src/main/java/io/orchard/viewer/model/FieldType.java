package io.orchard.viewer.model;

/**
 * The VRML97/X3D field types this loader understands, with how many numbers one value holds.
 * Values are stored as: {@code Boolean}; {@code Integer}; {@code Double} for SFFloat and SFTime;
 * {@code float[]} for SFVec2f/SFVec3f/SFColor/SFRotation and for every numeric MF type (flat);
 * {@code int[]} for MFInt32; {@code String}; {@code List<String>}; {@link SceneNode} (null for
 * NULL); {@code List<SceneNode>}.
 */
public enum FieldType {
    /** One boolean. */
    SFBOOL("SFBool", 0, false),
    /** One 32-bit integer. */
    SFINT32("SFInt32", 1, false),
    /** One number. */
    SFFLOAT("SFFloat", 1, false),
    /** One time, in seconds. */
    SFTIME("SFTime", 1, false),
    /** One 2D vector. */
    SFVEC2F("SFVec2f", 2, false),
    /** One 3D vector. */
    SFVEC3F("SFVec3f", 3, false),
    /** One RGB colour, each component 0 to 1. */
    SFCOLOR("SFColor", 3, false),
    /** One axis-angle rotation. */
    SFROTATION("SFRotation", 4, false),
    /** One string. */
    SFSTRING("SFString", 0, false),
    /** One node, or NULL. */
    SFNODE("SFNode", 0, false),
    /** A list of 32-bit integers. */
    MFINT32("MFInt32", 1, true),
    /** A list of numbers. */
    MFFLOAT("MFFloat", 1, true),
    /** A list of 2D vectors. */
    MFVEC2F("MFVec2f", 2, true),
    /** A list of 3D vectors. */
    MFVEC3F("MFVec3f", 3, true),
    /** A list of RGB colours. */
    MFCOLOR("MFColor", 3, true),
    /** A list of axis-angle rotations. */
    MFROTATION("MFRotation", 4, true),
    /** A list of strings. */
    MFSTRING("MFString", 0, true),
    /** A list of nodes. */
    MFNODE("MFNode", 0, true);

    private final String specName;
    private final int components;
    private final boolean multiple;

    FieldType(String specName, int components, boolean multiple) {
        this.specName = specName;
        this.components = components;
        this.multiple = multiple;
    }

    /** Numbers per value: 3 for SFVec3f and MFVec3f, 0 for non-numeric types. */
    public int components() {
        return components;
    }

    /** Whether the type holds a list of values (an MF type). */
    public boolean isMultiple() {
        return multiple;
    }

    /** Whether the field holds nodes: SFNode or MFNode. */
    public boolean isNode() {
        return this == SFNODE || this == MFNODE;
    }

    /** Whether the numbers must be integers: SFInt32 or MFInt32. */
    public boolean isInteger() {
        return this == SFINT32 || this == MFINT32;
    }

    /** Whether an SF value is stored as a {@code Double} rather than a {@code float[]}. */
    public boolean isScalar() {
        return this == SFFLOAT || this == SFTIME;
    }

    @Override
    public String toString() {
        return specName;
    }
}
