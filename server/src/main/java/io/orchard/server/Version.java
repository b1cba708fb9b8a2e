package io.orchard.server;

import java.io.IOException;
import java.io.InputStream;
import java.util.Properties;

/** The software version of this build, as the build stamped it into a resource. */
public final class Version {

    private static final String VERSION = load();

    private Version() {}

    /** The version, for example {@code 0.1.0}; "unknown" when the resource is missing. */
    public static String current() {
        return VERSION;
    }

    private static String load() {
        try (InputStream in = Version.class.getResourceAsStream("version.properties")) {
            if (in == null) {
                return "unknown";
            }
            Properties properties = new Properties();
            properties.load(in);
            String version = properties.getProperty("version", "unknown");
            return version.startsWith("${") ? "unknown" : version;
        } catch (IOException e) {
            return "unknown";
        }
    }
}
