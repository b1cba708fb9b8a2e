package io.orchard.viewer.model;

/**
 * The VRML97/X3D field types this loader understands, with how many numbers one value holds.
 * Values are stored as: {@code Boolean}; {@code Integer}; {@code Double} for SFFloat and SFTime;
 * {@code float[]} for SFVec2f/SFVec3f/SFColor/SFRotation and for every numeric MF type (flat);
 * {@code int[]} for MFInt32; {@code String}; {@code List<String>}; {@link SceneNode} (null for
 * NULL); {@code List<SceneNode>}.
 */
public enum FieldType {
    SFBOOL("SFBool", 0, false),
    SFINT32("SFInt32", 1, false),
    SFFLOAT("SFFloat", 1, false),
    SFTIME("SFTime", 1, false),
    SFVEC2F("SFVec2f", 2, false),
    SFVEC3F("SFVec3f", 3, false),
    SFCOLOR("SFColor", 3, false),
    SFROTATION("SFRotation", 4, false),
    SFSTRING("SFString", 0, false),
    SFNODE("SFNode", 0, false),
    MFINT32("MFInt32", 1, true),
    MFFLOAT("MFFloat", 1, true),
    MFVEC2F("MFVec2f", 2, true),
    MFVEC3F("MFVec3f", 3, true),
    MFCOLOR("MFColor", 3, true),
    MFROTATION("MFRotation", 4, true),
    MFSTRING("MFString", 0, true),
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

    public boolean isMultiple() {
        return multiple;
    }

    public boolean isNode() {
        return this == SFNODE || this == MFNODE;
    }

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
