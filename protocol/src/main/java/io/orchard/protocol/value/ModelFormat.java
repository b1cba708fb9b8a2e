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
    BUNDLED("bundled");

    private final String wireName;

    ModelFormat(String wireName) {
        this.wireName = wireName;
    }

    /** The name of this value on the wire. */
    @JsonValue
    public String wireName() {
        return wireName;
    }
}
