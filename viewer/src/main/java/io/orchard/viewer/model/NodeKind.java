package io.orchard.viewer.model;

/** Where a node may appear: the roles of the VRML97 node type hierarchy that this loader uses. */
public enum NodeKind {
    /** Anything allowed in a grouping node's children: groups, shapes, sensors, interpolators. */
    CHILD("a child node"),
    /** Box, Sphere, IndexedFaceSet and the other geometry nodes. */
    GEOMETRY("a geometry node"),
    /** An Appearance node, a Shape's appearance. */
    APPEARANCE("an Appearance node"),
    /** A Material node, an Appearance's material. */
    MATERIAL("a Material node"),
    /** A texture node, such as ImageTexture. */
    TEXTURE("a texture node"),
    /** A Coordinate node: the points of a face or line set. */
    COORDINATE("a Coordinate node"),
    /** A Normal node: the normals of a face set. */
    NORMAL("a Normal node"),
    /** A Color node: per-vertex or per-face colours. */
    COLOR("a Color node"),
    /** A TextureCoordinate node: where the texture maps onto a face set. */
    TEXTURE_COORDINATE("a TextureCoordinate node"),
    /** Anything at all (fields of node types this loader does not build). */
    ANY("a node");

    private final String description;

    NodeKind(String description) {
        this.description = description;
    }

    /** The kind in words, such as {@code "a Material node"}, for error messages. */
    public String description() {
        return description;
    }
}
