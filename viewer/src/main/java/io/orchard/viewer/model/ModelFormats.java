package io.orchard.viewer.model;

import io.orchard.protocol.value.ModelFormat;
import java.nio.charset.StandardCharsets;
import java.util.Locale;
import java.util.Optional;

/**
 * Tells which of the protocol's {@link ModelFormat}s a model file is in, from its name or from
 * its first bytes. The paper's agents were VRML97 files; X3D is their XML successor and glTF the
 * format today's tools export, so all of them are read and give the same {@link BodyModel}.
 * {@link ModelFormat#BUNDLED} names one of the viewer's own models and is never a file's format.
 */
public final class ModelFormats {

    private static final int SNIFF_BYTES = 512;

    private ModelFormats() {
    }

    /**
     * The format a file name's extension announces, if any: {@code .gltf}, {@code .glb},
     * {@code .x3d}, {@code .wrl} or {@code .vrml}. Compressed variants ({@code .wrz},
     * {@code .x3dz}) are not accepted.
     */
    public static Optional<ModelFormat> fromFileName(String fileName) {
        String name = fileName.toLowerCase(Locale.ROOT);
        int dot = name.lastIndexOf('.');
        if (dot < 0) {
            return Optional.empty();
        }
        return switch (name.substring(dot + 1)) {
            case "gltf" -> Optional.of(ModelFormat.GLTF);
            case "glb" -> Optional.of(ModelFormat.GLB);
            case "x3d" -> Optional.of(ModelFormat.X3D);
            case "wrl", "vrml" -> Optional.of(ModelFormat.VRML97);
            default -> Optional.empty();
        };
    }

    /**
     * The format the first bytes show, if they are conclusive: the GLB magic, the VRML97 header
     * line, an XML document whose first element is {@code X3D}, or a JSON object with an
     * {@code "asset"} member. Only a prefix is examined, so this is cheap on large inputs.
     */
    public static Optional<ModelFormat> detect(byte[] bytes) {
        if (bytes.length >= 4 && bytes[0] == 'g' && bytes[1] == 'l' && bytes[2] == 'T'
                && bytes[3] == 'F') {
            return Optional.of(ModelFormat.GLB);
        }
        String head = new String(bytes, 0, Math.min(bytes.length, SNIFF_BYTES),
                StandardCharsets.UTF_8);
        if (head.startsWith("\uFEFF")) {
            head = head.substring(1);
        }
        if (head.startsWith("#VRML V2.0")) {
            return Optional.of(ModelFormat.VRML97);
        }
        String trimmed = head.stripLeading();
        if (trimmed.startsWith("<") && (trimmed.contains("<X3D") || trimmed.contains("X3D "))) {
            return Optional.of(ModelFormat.X3D);
        }
        if (trimmed.startsWith("{") && trimmed.contains("\"asset\"")) {
            return Optional.of(ModelFormat.GLTF);
        }
        return Optional.empty();
    }

    /** The detected format if the bytes are conclusive, else the one the file name announces. */
    public static Optional<ModelFormat> detect(String fileName, byte[] bytes) {
        Optional<ModelFormat> sniffed = detect(bytes);
        return sniffed.isPresent() ? sniffed : fromFileName(fileName);
    }
}
