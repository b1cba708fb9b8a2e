package io.orchard.protocol.value;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.net.URLDecoder;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.zip.ZipEntry;
import java.util.zip.ZipException;
import java.util.zip.ZipInputStream;
import java.util.zip.ZipOutputStream;

/**
 * The files of a model sent as a zip ({@link ModelFormat#ZIP}): one model file ({@code .gltf},
 * {@code .glb}, {@code .x3d} or {@code .wrl}) and the files it refers to, unpacked in memory and
 * checked so that a viewer given one can read it safely. An archive is refused, with an exception
 * naming the entry and the rule, when its files unpack to more than {@link ModelSpec#MAX_MODEL_BYTES}
 * together, when they unpack to more than {@value #MAX_RATIO} times their packed size (a zip bomb),
 * when it has more than {@value #MAX_ENTRIES} entries, two entries of one name, a name that is
 * absolute, has a {@code ..} or {@code .} segment, a backslash or a control character, a symbolic
 * link, an encrypted entry, or when it holds no model file or several at the shallowest level that
 * has one. Nothing is ever written to disk.
 *
 * <p>A file's references ({@link #resolve}) are paths relative to the folder of the file that makes
 * them, percent-decoded, and must name a file of the archive: no scheme, no absolute path, nothing
 * outside the archive.
 */
public final class ModelArchive {

    /** The most entries (files and folders) an archive may have. */
    public static final int MAX_ENTRIES = 256;

    /** How many times their packed size the files may unpack to, once past the first {@value #RATIO_FREE} bytes. */
    public static final int MAX_RATIO = 100;

    /** Bytes that may unpack at any ratio: small files compress well and are no bomb. */
    public static final int RATIO_FREE = 64 * 1024;

    /** The model files an archive may hold, by extension, and their formats. */
    public static final Map<String, ModelFormat> MODEL_EXTENSIONS = Map.of(".gltf", ModelFormat.GLTF,
            ".glb", ModelFormat.GLB, ".x3d", ModelFormat.X3D, ".wrl", ModelFormat.VRML97);

    private static final int LOCAL_HEADER = 0x04034b50;
    private static final int CENTRAL_HEADER = 0x02014b50;
    private static final int END_OF_DIRECTORY = 0x06054b50;
    private static final int UNIX = 3;
    private static final int FILE_TYPE = 0170000;
    private static final int SYMBOLIC_LINK = 0120000;

    private final Map<String, byte[]> files;
    private final String model;

    private ModelArchive(Map<String, byte[]> files, String model) {
        this.files = Collections.unmodifiableMap(files);
        this.model = model;
    }

    /**
     * Unpacks and checks a zip.
     *
     * @throws IllegalArgumentException naming the entry and the rule it breaks
     */
    public static ModelArchive read(byte[] zip) {
        if (zip.length < 4 || ByteBuffer.wrap(zip).order(ByteOrder.LITTLE_ENDIAN).getInt(0) != LOCAL_HEADER) {
            throw new IllegalArgumentException("the zip does not start with a zip entry's header (bytes 50 4B 03 04)");
        }
        List<String> central = CentralDirectory.names(zip);
        Map<String, byte[]> files = new LinkedHashMap<>();
        List<String> seen = new ArrayList<>();
        long total = 0;
        try (ZipInputStream in = new ZipInputStream(new ByteArrayInputStream(zip), StandardCharsets.UTF_8)) {
            ZipEntry entry;
            while ((entry = in.getNextEntry()) != null) {
                String name = entry.getName();
                if (seen.size() == MAX_ENTRIES) {
                    throw new IllegalArgumentException("the zip has more than " + MAX_ENTRIES + " entries");
                }
                checkName(name);
                if (seen.contains(name)) {
                    throw new IllegalArgumentException("the zip has two entries named " + Checks.quote(name));
                }
                seen.add(name);
                if (entry.isDirectory()) {
                    continue;
                }
                byte[] bytes = unpack(in, name, ModelSpec.MAX_MODEL_BYTES - total);
                total += bytes.length;
                long allowed = (long) MAX_RATIO * zip.length + RATIO_FREE;
                if (total > allowed) {
                    throw new IllegalArgumentException("the zip's files unpack to more than " + MAX_RATIO
                            + " times its " + zip.length + " bytes (at entry " + Checks.quote(name)
                            + "): refused as a zip bomb");
                }
                files.put(name, bytes);
            }
        } catch (ZipException e) {
            throw new IllegalArgumentException("the zip cannot be read: " + e.getMessage(), e);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        if (!central.equals(seen)) {
            throw new IllegalArgumentException("the zip's central directory lists " + central.size()
                    + " entries that differ from the " + seen.size() + " entries it holds");
        }
        return new ModelArchive(files, modelFile(files));
    }

    private static byte[] unpack(InputStream in, String name, long room) throws IOException {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        byte[] buffer = new byte[16 * 1024];
        int read;
        while ((read = in.read(buffer)) > 0) {
            if (out.size() + read > room) {
                throw new IllegalArgumentException("the zip's files unpack to more than " + ModelSpec.MAX_MODEL_BYTES
                        + " bytes (at entry " + Checks.quote(name) + ")");
            }
            out.write(buffer, 0, read);
        }
        return out.toByteArray();
    }

    private static void checkName(String name) {
        String why = null;
        if (name.isEmpty()) {
            why = "is empty";
        } else if (name.startsWith("/") || name.matches("^[A-Za-z]:.*")) {
            why = "is an absolute path";
        } else if (name.indexOf('\\') >= 0) {
            why = "has a backslash (folders are separated by '/')";
        } else if (name.chars().anyMatch(c -> c < 0x20 || c == 0x7f)) {
            why = "has a control character";
        } else {
            String path = name.endsWith("/") ? name.substring(0, name.length() - 1) : name;
            for (String segment : path.split("/", -1)) {
                if (segment.equals("..")) {
                    why = "has a '..' segment, which would leave the archive";
                } else if (segment.equals(".") || segment.isEmpty()) {
                    why = "has an empty or '.' segment";
                }
            }
        }
        if (why != null) {
            throw new IllegalArgumentException("the zip's entry " + Checks.quote(name) + " " + why);
        }
    }

    private static String modelFile(Map<String, byte[]> files) {
        int shallowest = Integer.MAX_VALUE;
        List<String> models = new ArrayList<>();
        for (String name : files.keySet()) {
            if (formatOf(name).isEmpty()) {
                continue;
            }
            int depth = name.split("/").length;
            if (depth < shallowest) {
                shallowest = depth;
                models.clear();
            }
            if (depth == shallowest) {
                models.add(name);
            }
        }
        if (models.isEmpty()) {
            throw new IllegalArgumentException("the zip holds no model file (one of .gltf, .glb, .x3d, .wrl) among "
                    + files.keySet());
        }
        if (models.size() > 1) {
            throw new IllegalArgumentException("the zip holds " + models.size() + " model files side by side, "
                    + models + "; it must hold one, with the files it refers to (an X3D Inline's file in a folder"
                    + " below it)");
        }
        return models.get(0);
    }

    private static Optional<ModelFormat> formatOf(String name) {
        int dot = name.lastIndexOf('.');
        return dot < 0 || name.lastIndexOf('/') > dot ? Optional.empty()
                : Optional.ofNullable(MODEL_EXTENSIONS.get(name.substring(dot).toLowerCase(Locale.ROOT)));
    }

    /** The model file's path in the archive. */
    public String modelPath() {
        return model;
    }

    /** The model file's format, from its extension. */
    public ModelFormat modelFormat() {
        return formatOf(model).orElseThrow();
    }

    /** The model file's bytes. */
    public byte[] modelBytes() {
        return files.get(model).clone();
    }

    /** Every file's path in the archive, in the archive's order (folders left out). */
    public List<String> paths() {
        return List.copyOf(files.keySet());
    }

    /** The bytes of the file at {@code path}, if the archive has it. */
    public Optional<byte[]> file(String path) {
        byte[] bytes = files.get(path);
        return bytes == null ? Optional.empty() : Optional.of(bytes.clone());
    }

    /**
     * The path in the archive that {@code uri}, written in the file at {@code from}, refers to.
     *
     * @throws IllegalArgumentException naming the URI when it has a scheme, is absolute, leaves the
     *                                  archive, or names no file of it
     */
    public String resolve(String from, String uri) {
        String where = Checks.quote(uri) + " in " + Checks.quote(from);
        String path;
        try {
            path = URLDecoder.decode(uri.replace("+", "%2B"), StandardCharsets.UTF_8);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException(where + " is not a well-formed URI: " + e.getMessage(), e);
        }
        if (path.matches("^[A-Za-z][A-Za-z0-9+.-]*:.*") || path.startsWith("/") || path.startsWith("\\")) {
            throw new IllegalArgumentException(where + " is not a path relative to the file: only files of the"
                    + " archive are read, never a URL or an absolute path");
        }
        List<String> segments = new ArrayList<>(List.of(from.split("/")));
        segments.remove(segments.size() - 1);
        for (String segment : path.split("/")) {
            if (segment.equals("..")) {
                if (segments.isEmpty()) {
                    throw new IllegalArgumentException(where + " leaves the archive");
                }
                segments.remove(segments.size() - 1);
            } else if (!segment.equals(".") && !segment.isEmpty()) {
                segments.add(segment);
            }
        }
        String resolved = String.join("/", segments);
        if (!files.containsKey(resolved)) {
            throw new IllegalArgumentException(where + " names " + Checks.quote(resolved)
                    + ", which the archive does not hold; it holds " + files.keySet());
        }
        return resolved;
    }

    /**
     * Packs files into a zip, in the order given, for a model's author (or a test) to send.
     *
     * @param files path in the archive to bytes; paths are checked as {@link #read} checks them
     */
    public static byte[] pack(Map<String, byte[]> files) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        try (ZipOutputStream zip = new ZipOutputStream(out, StandardCharsets.UTF_8)) {
            for (Map.Entry<String, byte[]> file : files.entrySet()) {
                checkName(file.getKey());
                ZipEntry entry = new ZipEntry(file.getKey());
                // A fixed time: the same files make the same zip, for games that repeat byte for byte.
                entry.setTime(315532800000L);
                zip.putNextEntry(entry);
                zip.write(file.getValue());
                zip.closeEntry();
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return out.toByteArray();
    }

    /** Reads the names and kinds of a zip's entries from its central directory, where links are marked. */
    private static final class CentralDirectory {

        private CentralDirectory() {
        }

        static List<String> names(byte[] zip) {
            ByteBuffer buffer = ByteBuffer.wrap(zip).order(ByteOrder.LITTLE_ENDIAN);
            int end = -1;
            for (int at = zip.length - 22; at >= Math.max(0, zip.length - 22 - 0xffff); at--) {
                if (buffer.getInt(at) == END_OF_DIRECTORY) {
                    end = at;
                    break;
                }
            }
            if (end < 0) {
                throw new IllegalArgumentException("the zip has no end of central directory (truncated?)");
            }
            int count = Short.toUnsignedInt(buffer.getShort(end + 10));
            long offset = Integer.toUnsignedLong(buffer.getInt(end + 16));
            if (count > MAX_ENTRIES) {
                throw new IllegalArgumentException("the zip has " + count + " entries, at most " + MAX_ENTRIES
                        + " are read");
            }
            List<String> names = new ArrayList<>();
            long at = offset;
            for (int i = 0; i < count; i++) {
                if (at < 0 || at + 46 > zip.length || buffer.getInt((int) at) != CENTRAL_HEADER) {
                    throw new IllegalArgumentException("the zip's central directory is damaged at entry " + i);
                }
                int p = (int) at;
                int madeBy = Short.toUnsignedInt(buffer.getShort(p + 4)) >>> 8;
                int nameLength = Short.toUnsignedInt(buffer.getShort(p + 28));
                int extra = Short.toUnsignedInt(buffer.getShort(p + 30));
                int comment = Short.toUnsignedInt(buffer.getShort(p + 32));
                long attributes = Integer.toUnsignedLong(buffer.getInt(p + 38));
                if (p + 46L + nameLength > zip.length) {
                    throw new IllegalArgumentException("the zip's central directory is damaged at entry " + i);
                }
                String name = new String(zip, p + 46, nameLength, StandardCharsets.UTF_8);
                if (madeBy == UNIX && ((attributes >>> 16) & FILE_TYPE) == SYMBOLIC_LINK) {
                    throw new IllegalArgumentException("the zip's entry " + Checks.quote(name)
                            + " is a symbolic link; links are refused, as they may point outside the archive");
                }
                names.add(name);
                at = p + 46L + nameLength + extra + comment;
            }
            return names;
        }
    }
}
