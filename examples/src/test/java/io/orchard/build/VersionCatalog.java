package io.orchard.build;

import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The parts of gradle/libs.versions.toml that the builds share: its {@code [versions]} and
 * {@code [libraries]}. Reads the subset of TOML a version catalog uses: tables, one entry a line,
 * plain strings and one-line inline tables, {@code #} comments. Anything else is rejected with the
 * offending line, rather than misread.
 *
 * @param versions  the {@code [versions]} table
 * @param libraries the {@code [libraries]} table, by alias
 */
record VersionCatalog(Map<String, String> versions, Map<String, Library> libraries) {

    private static final Pattern TABLE = Pattern.compile("\\[(?<name>[\\w.-]+)]");
    private static final Pattern ENTRY = Pattern.compile("(?<key>[\\w.-]+)\\s*=\\s*(?<value>.+)");
    private static final Pattern STRING = Pattern.compile("\"(?<text>[^\"]*)\"");
    private static final Pattern FIELD = Pattern.compile("(?<key>[\\w.]+)\\s*=\\s*\"(?<text>[^\"]*)\"\\s*,?\\s*");
    private static final Set<String> LIBRARY_FIELDS = Set.of("module", "group", "name", "version", "version.ref");

    VersionCatalog {
        versions = Map.copyOf(versions);
        libraries = Map.copyOf(libraries);
    }

    /**
     * One {@code [libraries]} entry.
     *
     * @param version the version, or {@code null} when a platform (a BOM) supplies it
     */
    record Library(String alias, String group, String artifact, String version) {

        String module() {
            return group + ":" + artifact;
        }

        /** How a build script names this library: {@code libs.} and the alias with '.' for '-' and '_'. */
        String accessor() {
            return "libs." + alias.replace('-', '.').replace('_', '.');
        }
    }

    /** The library a build script names with {@code accessor}, such as {@code libs.jackson.databind}. */
    Optional<Library> byAccessor(String accessor) {
        return libraries.values().stream().filter(library -> library.accessor().equals(accessor)).findFirst();
    }

    static VersionCatalog parse(String toml) {
        Map<String, Map<String, String>> tables = new LinkedHashMap<>();
        Map<String, String> table = null;
        for (String rawLine : toml.split("\\R")) {
            String line = withoutComment(rawLine).strip();
            Matcher header = TABLE.matcher(line);
            Matcher entry = ENTRY.matcher(line);
            if (line.isEmpty()) {
                continue;
            } else if (header.matches()) {
                table = tables.computeIfAbsent(header.group("name"), name -> new LinkedHashMap<>());
            } else if (entry.matches() && table != null) {
                table.put(entry.group("key"), entry.group("value").strip());
            } else {
                throw new IllegalArgumentException(
                        "expected [table] or key = value inside a table in the version catalog, was: " + rawLine);
            }
        }

        Map<String, String> versions = new LinkedHashMap<>();
        tables.getOrDefault("versions", Map.of()).forEach((key, value) -> {
            Matcher string = STRING.matcher(value);
            if (!string.matches()) {
                throw new IllegalArgumentException(
                        "expected a plain version string for version " + key + ", was: " + value);
            }
            versions.put(key, string.group("text"));
        });
        Map<String, Library> libraries = new LinkedHashMap<>();
        tables.getOrDefault("libraries", Map.of()).forEach(
                (alias, value) -> libraries.put(alias, library(alias, value, versions)));
        return new VersionCatalog(versions, libraries);
    }

    /** Reads {@code "group:artifact[:version]"} or {@code { module = ..., version.ref = ... }}. */
    private static Library library(String alias, String value, Map<String, String> versions) {
        Matcher string = STRING.matcher(value);
        if (string.matches()) {
            String[] parts = string.group("text").split(":");
            if (parts.length < 2 || parts.length > 3) {
                throw new IllegalArgumentException(
                        "expected \"group:artifact[:version]\" for library " + alias + ", was: " + value);
            }
            return new Library(alias, parts[0], parts[1], parts.length == 3 ? parts[2] : null);
        }
        if (!value.startsWith("{") || !value.endsWith("}")) {
            throw new IllegalArgumentException(
                    "expected a string or a one-line inline table for library " + alias + ", was: " + value);
        }
        String body = value.substring(1, value.length() - 1).strip();
        Map<String, String> fields = new LinkedHashMap<>();
        Matcher field = FIELD.matcher(body);
        int end = 0;
        while (field.find() && field.start() == end) {
            fields.put(field.group("key"), field.group("text"));
            end = field.end();
        }
        if (end != body.length() || !LIBRARY_FIELDS.containsAll(fields.keySet())) {
            throw new IllegalArgumentException("expected only string fields " + LIBRARY_FIELDS
                    + " for library " + alias + ", was: " + value);
        }

        String module = fields.containsKey("module")
                ? fields.get("module")
                : fields.get("group") + ":" + fields.get("name");
        String[] parts = module.split(":");
        if (parts.length != 2 || parts[0].equals("null") || parts[1].equals("null")) {
            throw new IllegalArgumentException(
                    "expected module = \"group:artifact\" or group and name for library " + alias + ", was: " + value);
        }
        String version = fields.get("version");
        String versionRef = fields.get("version.ref");
        if (versionRef != null) {
            version = versions.get(versionRef);
            if (version == null) {
                throw new IllegalArgumentException("library " + alias + " refers to version " + versionRef
                        + ", expected one of [versions] " + versions.keySet());
            }
        }
        return new Library(alias, parts[0], parts[1], version);
    }

    /** The line up to a {@code #} that is not inside a string. */
    private static String withoutComment(String line) {
        boolean inString = false;
        for (int i = 0; i < line.length(); i++) {
            char c = line.charAt(i);
            if (c == '"') {
                inString = !inString;
            } else if (c == '#' && !inString) {
                return line.substring(0, i);
            }
        }
        return line;
    }
}
