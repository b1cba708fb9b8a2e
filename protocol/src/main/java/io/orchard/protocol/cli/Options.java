package io.orchard.protocol.cli;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The command-line options of Orchard's programs: {@code --name value}, {@code --name=value} and
 * flags, each declared with its help text, so that {@code --help} and the errors always match what
 * is accepted. Shared by the server, the viewer and the agents so that they all read alike.
 *
 * <pre>{@code
 * Options options = new Options("orchard server", "Runs the world server.")
 *         .value("port", "N", "TCP port, 0 for any free one", "7557")
 *         .flag("lockstep", "advance when every agent has ended its turn");
 * Options.Parsed parsed = options.parse(args); // throws UsageException naming the bad option
 * int port = parsed.integer("port", 0, 65535);
 * }</pre>
 */
public final class Options {

    private record Option(String name, String argument, String help, String defaultValue, boolean repeatable) {}

    private final String command;
    private final String summary;
    private final Map<String, Option> options = new LinkedHashMap<>();

    /**
     * A command's options, none declared yet.
     *
     * @param command how the command is typed, for the usage line
     * @param summary one sentence on what it does
     */
    public Options(String command, String summary) {
        this.command = command;
        this.summary = summary;
    }

    /** Declares an option that takes a value; {@code defaultValue} may be null. */
    public Options value(String name, String argument, String help, String defaultValue) {
        options.put(name, new Option(name, argument, help, defaultValue, false));
        return this;
    }

    /** Declares an option that takes a value and may be given more than once. */
    public Options repeatable(String name, String argument, String help) {
        options.put(name, new Option(name, argument, help, null, true));
        return this;
    }

    /** Declares a flag, an option without a value. */
    public Options flag(String name, String help) {
        options.put(name, new Option(name, null, help, null, false));
        return this;
    }

    /** The help text: usage, summary and every option with its default. */
    public String help() {
        StringBuilder text = new StringBuilder("Usage: ").append(command).append(" [options]\n\n")
                .append(summary).append("\n\nOptions:\n");
        List<Option> all = new ArrayList<>(options.values());
        all.add(new Option("help", null, "print this help and exit", null, false));
        for (Option option : all) {
            String left = "  --" + option.name() + (option.argument() == null ? "" : " " + option.argument());
            text.append(String.format("%-28s %s", left, option.help()));
            if (option.defaultValue() != null) {
                text.append(" (default: ").append(option.defaultValue()).append(')');
            }
            if (option.repeatable()) {
                text.append(" (repeatable)");
            }
            text.append('\n');
        }
        return text.toString();
    }

    /**
     * Reads the arguments.
     *
     * @throws UsageException naming an unknown option, a missing value or a stray argument
     */
    public Parsed parse(List<String> args) throws UsageException {
        Map<String, List<String>> values = new LinkedHashMap<>();
        for (int i = 0; i < args.size(); i++) {
            String arg = args.get(i);
            if (!arg.startsWith("--")) {
                throw new UsageException("unexpected argument '" + arg + "' (options start with --; see --help)");
            }
            String name = arg.substring(2);
            String value = null;
            int equals = name.indexOf('=');
            if (equals >= 0) {
                value = name.substring(equals + 1);
                name = name.substring(0, equals);
            }
            if (name.equals("help")) {
                values.put("help", List.of("true"));
                continue;
            }
            Option option = options.get(name);
            if (option == null) {
                throw new UsageException("unknown option --" + name + "; known options: " + String.join(", ",
                        options.keySet().stream().map(n -> "--" + n).toList()));
            }
            if (option.argument() == null) {
                if (value != null) {
                    throw new UsageException("--" + name + " takes no value, was given '" + value + "'");
                }
                value = "true";
            } else if (value == null) {
                if (i + 1 >= args.size() || args.get(i + 1).startsWith("--")) {
                    throw new UsageException("--" + name + " needs a value: " + option.argument());
                }
                value = args.get(++i);
            }
            List<String> list = values.computeIfAbsent(name, n -> new ArrayList<>());
            if (!list.isEmpty() && !option.repeatable()) {
                throw new UsageException("--" + name + " given twice");
            }
            list.add(value);
        }
        return new Parsed(values);
    }

    /** Parsed options, with typed accessors that name the option and the bad value on error. */
    public final class Parsed {

        private final Map<String, List<String>> values;

        private Parsed(Map<String, List<String>> values) {
            this.values = values;
        }

        /** Whether --help was given. */
        public boolean help() {
            return values.containsKey("help");
        }

        /** Whether the option or flag was given. */
        public boolean has(String name) {
            return values.containsKey(name);
        }

        /** The option's value, its default, or null. */
        public String string(String name) {
            List<String> given = values.get(name);
            if (given != null) {
                return given.get(0);
            }
            Option option = options.get(name);
            return option == null ? null : option.defaultValue();
        }

        /** Every value of a repeatable option, in order. */
        public List<String> all(String name) {
            return List.copyOf(values.getOrDefault(name, List.of()));
        }

        /** The option as an integer within [min, max]; null when absent without a default. */
        public Integer integer(String name, int min, int max) throws UsageException {
            Long value = longValue(name, min, max);
            return value == null ? null : value.intValue();
        }

        /** The option as a long within [min, max]; null when absent without a default. */
        public Long longValue(String name, long min, long max) throws UsageException {
            String text = string(name);
            if (text == null) {
                return null;
            }
            long value;
            try {
                value = Long.parseLong(text.strip());
            } catch (NumberFormatException e) {
                throw new UsageException("--" + name + " must be a whole number, was '" + text + "'");
            }
            if (value < min || value > max) {
                throw new UsageException("--" + name + " must be " + min + " to " + max + ", was " + value);
            }
            return value;
        }

        /** The option as a number within [min, max]; null when absent without a default. */
        public Double number(String name, double min, double max) throws UsageException {
            String text = string(name);
            if (text == null) {
                return null;
            }
            double value;
            try {
                value = Double.parseDouble(text.strip());
            } catch (NumberFormatException e) {
                throw new UsageException("--" + name + " must be a number, was '" + text + "'");
            }
            if (!(value >= min && value <= max)) {
                throw new UsageException("--" + name + " must be " + min + " to " + max + ", was " + text);
            }
            return value;
        }

        /** The option as one of the allowed words (case-insensitive), returned in lower case. */
        public String choice(String name, String... allowed) throws UsageException {
            String text = string(name);
            if (text == null) {
                return null;
            }
            for (String word : allowed) {
                if (word.equalsIgnoreCase(text.strip())) {
                    return word;
                }
            }
            throw new UsageException("--" + name + " must be one of " + String.join(", ", allowed) + ", was '"
                    + text + "'");
        }
    }
}
