package io.orchard.viewer.agent;

import io.orchard.protocol.value.ModelSpec;
import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The models the viewer ships, for agents that register with {@code {"format":"bundled",
 * "bundled":"figure"}} instead of sending a file. Each is an X3D file written for an agent named
 * after the model with a capital letter ({@code Figure}, {@code Bunny}); before loading, every
 * DEF name that starts with that word is renamed to start with the agent's name instead, so an
 * agent {@code Guppy} with the bundled figure has the Transform {@code Guppy}, the movers
 * {@code GuppyMover} and {@code GuppyTSMover} and the animation {@code GuppyTSWalk}. Joint names
 * ({@code LeftHip}, {@code Neck}) stay as they are. The model is scaled to the agent's height.
 */
public final class BundledModels {

    /** The bundled models, by the name an agent gives: the protocol's list, which the server checks registrations by. */
    public static final List<String> NAMES = ModelSpec.BUNDLED_NAMES;

    private static final Pattern NAMED = Pattern.compile("\\b(DEF|USE|fromNode|toNode)=(['\"])([A-Za-z][A-Za-z0-9_-]*)\\2");
    private static final Pattern HEIGHT =
            Pattern.compile("<meta\\s+name=['\"]orchard-height['\"]\\s+content=['\"]([0-9.]+)['\"]");

    private BundledModels() {
    }

    /** The X3D text of a bundled model, as shipped; empty when there is no model of that name. */
    public static Optional<String> source(String name) {
        if (!NAMES.contains(name)) {
            return Optional.empty();
        }
        try (InputStream in = BundledModels.class.getResourceAsStream("/io/orchard/viewer/bundled/" + name + ".x3d")) {
            if (in == null) {
                throw new IllegalStateException("bundled model " + name + " is missing from the viewer's resources");
            }
            return Optional.of(new String(in.readAllBytes(), StandardCharsets.UTF_8));
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read bundled model " + name, e);
        }
    }

    /**
     * A bundled model fitted to one agent: DEF names renamed after the agent, and sized to its
     * height.
     *
     * @param name      the bundled model's name, one of {@link #NAMES}
     * @param agentName the agent's name
     * @param height    the agent's body height in units
     * @return the X3D bytes, or empty when there is no bundled model of that name
     */
    public static Optional<byte[]> fitted(String name, String agentName, double height) {
        return source(name).map(text -> fit(text, prefix(name), agentName, height).getBytes(StandardCharsets.UTF_8));
    }

    static String fit(String text, String prefix, String agentName, double height) {
        Matcher nominal = HEIGHT.matcher(text);
        double scale = nominal.find() ? height / Double.parseDouble(nominal.group(1)) : 1;
        String sized = text.replace("DEF='" + prefix + "Size'", "DEF='" + prefix + "Size' scale='"
                + number(scale) + " " + number(scale) + " " + number(scale) + "'");
        Matcher names = NAMED.matcher(sized);
        StringBuilder out = new StringBuilder();
        while (names.find()) {
            String defName = names.group(3);
            String renamed = defName.startsWith(prefix) ? agentName + defName.substring(prefix.length()) : defName;
            names.appendReplacement(out, Matcher.quoteReplacement(names.group(1) + "=" + names.group(2) + renamed
                    + names.group(2)));
        }
        names.appendTail(out);
        return out.toString();
    }

    private static String prefix(String name) {
        return name.substring(0, 1).toUpperCase(Locale.ROOT) + name.substring(1);
    }

    private static String number(double value) {
        return String.format(Locale.ROOT, "%.4f", value);
    }
}
