package io.orchard.viewer.model;

/** Where a node may appear: the roles of the VRML97 node type hierarchy that this loader uses. */
public enum NodeKind {
    /** Anything allowed in a grouping node's children: groups, shapes, sensors, interpolators. */
    CHILD("a child node"),
    GEOMETRY("a geometry node"),
    APPEARANCE("an Appearance node"),
    MATERIAL("a Material node"),
    TEXTURE("a texture node"),
    COORDINATE("a Coordinate node"),
    NORMAL("a Normal node"),
    COLOR("a Color node"),
    TEXTURE_COORDINATE("a TextureCoordinate node"),
    /** Anything at all (fields of node types this loader does not build). */
    ANY("a node");

    private final String description;

    NodeKind(String description) {
        this.description = description;
    }

    public String description() {
        return description;
    }
}
