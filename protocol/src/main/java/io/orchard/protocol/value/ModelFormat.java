package io.orchard.protocol.value;

import com.fasterxml.jackson.annotation.JsonValue;

/**
 * The formats of an agent's visual model.
 */
public enum ModelFormat {
    /** glTF 2.0 JSON with its buffers embedded as data URIs. */
    GLTF("gltf"),

    /** Binary glTF 2.0. */
    GLB("glb"),

    /** X3D in its XML encoding. */
    X3D("x3d"),

    /** VRML97 (VRML 2.0, classic encoding), the paper's own format. */
    VRML97("vrml97"),

    /** One of the models the viewer ships, named instead of sent. */
    BUNDLED("bundled"),

    /**
     * A zip of one model file and the files it refers to (version 2): a glTF with its buffers and
     * textures beside it, an X3D with its textures and {@code Inline} files; see {@link ModelArchive}.
     */
    ZIP("zip");

    private final String wireName;

    ModelFormat(String wireName) {
        this.wireName = wireName;
    }

    /** Whether a client of protocol version 1 knows this format. */
    public boolean inVersion1() {
        return this != ZIP;
    }

    /** The name of this value on the wire. */
    @JsonValue
    public String wireName() {
        return wireName;
    }
}
