package io.orchard.web;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.HashMap;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;

/**
 * The page's files, read once from the jar: exactly those that files.txt lists, so that no other
 * path can be asked for, however it is spelt.
 */
final class Site {

    private static final String ROOT = "/io/orchard/web/site/";

    private static final Map<String, String> TYPES = Map.of(
            "html", "text/html; charset=utf-8",
            "js", "text/javascript; charset=utf-8",
            "css", "text/css; charset=utf-8",
            "png", "image/png",
            "svg", "image/svg+xml",
            "ico", "image/x-icon",
            "json", "application/json",
            "x3d", "model/x3d+xml");

    /** A file of the site: what it holds and its content type. */
    record File(byte[] bytes, String type) {}

    private final Map<String, File> files;

    Site(Map<String, File> files) {
        this.files = Map.copyOf(files);
    }

    static Site fromJar() throws IOException {
        Map<String, File> files = new HashMap<>();
        for (String path : read("files.txt").lines().map(String::strip).filter(line -> !line.isEmpty()).toList()) {
            files.put("/" + path, new File(bytes(path), type(path)));
        }
        if (!files.containsKey("/index.html")) {
            throw new IOException("the browser viewer's page is missing from the class path (expected " + ROOT
                    + "index.html, which the web module's build puts there)");
        }
        return new Site(files);
    }

    /** The file at a request's path ("/" is the page), or empty. */
    Optional<File> find(String path) {
        return Optional.ofNullable(files.get(path.equals("/") ? "/index.html" : path));
    }

    static String type(String path) {
        String extension = path.substring(path.lastIndexOf('.') + 1).toLowerCase(Locale.ROOT);
        return TYPES.getOrDefault(extension, "application/octet-stream");
    }

    private static String read(String path) throws IOException {
        return new String(bytes(path), StandardCharsets.UTF_8);
    }

    private static byte[] bytes(String path) throws IOException {
        try (InputStream in = Site.class.getResourceAsStream(ROOT + path)) {
            if (in == null) {
                throw new IOException("the browser viewer's file " + ROOT + path + " is missing from the class path"
                        + " (expected the web module's build to put it there)");
            }
            return in.readAllBytes();
        } catch (UncheckedIOException e) {
            throw e.getCause();
        }
    }
}
