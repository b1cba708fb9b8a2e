package io.orchard.viewer.model;

import io.orchard.protocol.value.ModelArchive;
import io.orchard.protocol.value.ModelFormat;
import io.orchard.viewer.model.ModelException.Kind;
import java.util.ArrayList;
import java.util.Base64;
import java.util.List;
import java.util.Locale;
import java.util.Optional;

/**
 * The files a model file may refer to: none for a model sent alone, the other files of its
 * {@link ModelArchive} for a model sent as a zip, each reference taken relative to the file that
 * makes it. Nothing outside the archive is ever read: a URL, an absolute path or a path that leaves
 * the archive is refused with a {@link ModelException} naming it.
 */
public final class ModelFiles {

    private static final ModelFiles NONE = new ModelFiles(null, null, List.of());

    private final ModelArchive archive;
    private final String from;
    private final List<String> inlining;

    private ModelFiles(ModelArchive archive, String from, List<String> inlining) {
        this.archive = archive;
        this.from = from;
        this.inlining = inlining;
    }

    /** No files: a model sent alone, whose only references that are read are {@code data:} URIs. */
    public static ModelFiles none() {
        return NONE;
    }

    /** The files of {@code archive}, as its model file refers to them. */
    public static ModelFiles of(ModelArchive archive) {
        return new ModelFiles(archive, archive.modelPath(), List.of(archive.modelPath()));
    }

    /**
     * Unpacks a zip of a model, refusing what {@link ModelArchive} refuses.
     *
     * @throws ModelException naming the entry and the rule, as the server would
     */
    public static ModelArchive unpack(byte[] zip, ModelLimits limits) throws ModelException {
        ModelArchive archive;
        try {
            archive = ModelArchive.read(zip);
        } catch (IllegalArgumentException e) {
            throw new ModelException(Kind.UNSAFE, "zip model refused: " + e.getMessage(), e);
        }
        long total = 0;
        for (String path : archive.paths()) {
            total += archive.file(path).orElseThrow().length;
        }
        if (total > limits.maxInputBytes()) {
            throw new ModelException(Kind.TOO_LARGE, "zip model's files unpack to " + total
                    + " bytes, more than the limit of " + limits.maxInputBytes());
        }
        return archive;
    }

    /** Whether references to files are read at all. */
    public boolean any() {
        return archive != null;
    }

    /** The path of the file whose references these are, for messages; "the model" without an archive. */
    public String path() {
        return archive == null ? "the model" : from;
    }

    /**
     * A reference made self-contained: a {@code data:} URI carrying the file {@code uri} names, or
     * {@code uri} as it is when it is a {@code data:} URI already or there are no files.
     *
     * @throws ModelException when the archive refuses the reference
     */
    public String embedded(String uri, String where) throws ModelException {
        if (archive == null || DataUriImages.isDataUri(uri)) {
            return uri;
        }
        byte[] bytes = archive.file(resolve(uri, where)).orElseThrow();
        return "data:" + mediaType(uri) + ";base64," + Base64.getEncoder().encodeToString(bytes);
    }

    /** {@link #embedded} for each of several references, as an MFString field holds them. */
    public List<String> embedded(List<String> uris, String where) throws ModelException {
        List<String> out = new ArrayList<>(uris.size());
        for (String uri : uris) {
            out.add(embedded(uri, where));
        }
        return out;
    }

    /**
     * The first of {@code uris} that names a file of the archive, for an {@code Inline}: its format,
     * its bytes and the files as it refers to them.
     *
     * @throws ModelException when no files are read, a reference is refused, the file is not a
     *                        model file, or the file inlines itself
     */
    public Inlined inline(List<String> uris, String where) throws ModelException {
        if (archive == null) {
            throw new ModelException(Kind.UNSAFE, where + ": Inline " + uris + " is not read: only a"
                    + " file inside the model's own zip is, and this model was sent alone");
        }
        if (uris.isEmpty()) {
            throw new ModelException(Kind.BAD_VALUE, where + ": Inline has no url");
        }
        String path = resolve(uris.get(0), where);
        int dot = path.lastIndexOf('.');
        ModelFormat format = dot < 0 ? null
                : ModelArchive.MODEL_EXTENSIONS.get(path.substring(dot).toLowerCase(Locale.ROOT));
        if (format != ModelFormat.X3D && format != ModelFormat.VRML97) {
            throw new ModelException(Kind.UNSUPPORTED, where + ": Inline '" + path + "' is not an"
                    + " X3D or VRML97 file");
        }
        if (inlining.contains(path)) {
            throw new ModelException(Kind.MALFORMED, where + ": Inline '" + path + "' inlines"
                    + " itself, through " + String.join(" -> ", inlining));
        }
        List<String> chain = new ArrayList<>(inlining);
        chain.add(path);
        return new Inlined(path, format, archive.file(path).orElseThrow(),
                new ModelFiles(archive, path, List.copyOf(chain)));
    }

    /**
     * A file an {@code Inline} names.
     *
     * @param path   its path in the archive
     * @param format X3D or VRML97
     * @param bytes  the file
     * @param files  the files as it refers to them
     */
    public record Inlined(String path, ModelFormat format, byte[] bytes, ModelFiles files) {
    }

    private String resolve(String uri, String where) throws ModelException {
        try {
            return archive.resolve(from, uri);
        } catch (IllegalArgumentException e) {
            throw new ModelException(Kind.UNSAFE, where + ": " + e.getMessage(), e);
        }
    }

    /** Bytes of a file this model refers to by {@code uri}, if it has files and names one. */
    public Optional<byte[]> read(String uri, String where) throws ModelException {
        return archive == null ? Optional.empty() : archive.file(resolve(uri, where));
    }

    private static String mediaType(String uri) {
        String lower = uri.toLowerCase(Locale.ROOT);
        if (lower.endsWith(".png")) {
            return "image/png";
        }
        if (lower.endsWith(".jpg") || lower.endsWith(".jpeg")) {
            return "image/jpeg";
        }
        return "application/octet-stream";
    }
}
