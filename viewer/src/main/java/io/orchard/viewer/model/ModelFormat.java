package io.orchard.viewer.model;

import java.nio.charset.StandardCharsets;
import java.util.Locale;
import java.util.Optional;

/**
 * The encodings an agent model may arrive in. The paper's agents were VRML97 files; X3D is their
 * XML successor and glTF the format today's tools export, so all three are accepted and give the
 * same {@link BodyModel}.
 */
public enum ModelFormat {
    /** glTF 2.0 JSON with every buffer and image embedded as a {@code data:} URI. */
    GLTF("gltf"),
    /** Binary glTF 2.0: one file holding the JSON and its binary buffer. */
    GLB("glb"),
    /** X3D in its XML encoding. */
    X3D("x3d"),
    /** VRML97, the classic {@code #VRML V2.0 utf8} encoding. */
    VRML97("wrl");

    private static final int SNIFF_BYTES = 512;

    private final String extension;

    ModelFormat(String extension) {
        this.extension = extension;
    }

    /** The usual file extension, without the dot. */
    public String extension() {
        return extension;
    }

    /**
     * The format a file name's extension announces, if any. Compressed variants ({@code .wrz},
     * {@code .x3dz}) are not accepted.
     */
    public static Optional<ModelFormat> fromFileName(String fileName) {
        String name = fileName.toLowerCase(Locale.ROOT);
        int dot = name.lastIndexOf('.');
        if (dot < 0) {
            return Optional.empty();
        }
        String ext = name.substring(dot + 1);
        for (ModelFormat format : values()) {
            if (format.extension.equals(ext)) {
                return Optional.of(format);
            }
        }
        return ext.equals("vrml") ? Optional.of(VRML97) : Optional.empty();
    }

    /**
     * The format the first bytes show, if they are conclusive: the GLB magic, the VRML97 header
     * line, an XML document whose first element is {@code X3D}, or a JSON object with an
     * {@code "asset"} member. Only a prefix is examined, so this is cheap on large inputs.
     */
    public static Optional<ModelFormat> detect(byte[] bytes) {
        if (bytes.length >= 4 && bytes[0] == 'g' && bytes[1] == 'l' && bytes[2] == 'T'
                && bytes[3] == 'F') {
            return Optional.of(GLB);
        }
        String head = new String(bytes, 0, Math.min(bytes.length, SNIFF_BYTES),
                StandardCharsets.UTF_8);
        if (head.startsWith("\uFEFF")) {
            head = head.substring(1);
        }
        if (head.startsWith("#VRML V2.0")) {
            return Optional.of(VRML97);
        }
        String trimmed = head.stripLeading();
        if (trimmed.startsWith("<") && (trimmed.contains("<X3D") || trimmed.contains("X3D "))) {
            return Optional.of(X3D);
        }
        if (trimmed.startsWith("{") && trimmed.contains("\"asset\"")) {
            return Optional.of(GLTF);
        }
        return Optional.empty();
    }

    /** The detected format if the bytes are conclusive, else the one the file name announces. */
    public static Optional<ModelFormat> detect(String fileName, byte[] bytes) {
        Optional<ModelFormat> sniffed = detect(bytes);
        return sniffed.isPresent() ? sniffed : fromFileName(fileName);
    }
}
