package io.orchard.agents.zoo;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Deque;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import javax.xml.stream.XMLInputFactory;
import javax.xml.stream.XMLStreamConstants;
import javax.xml.stream.XMLStreamException;
import javax.xml.stream.XMLStreamReader;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The conventions the zoo's agent models follow (see the README beside them), checked on the
 * files themselves with the JDK only: the root Transform named after the agent holds the whole
 * body, every joint a controller registers is a DEF'd Transform nested as a skeleton, every
 * animation is a DEF'd TimeSensor that stays idle until started and drives joints through
 * interpolators, every ROUTE connects defined nodes, and every model has the paper's movement
 * nodes (Guppy exactly as in the paper's Figure 5).
 */
class ModelConventionsTest {

    private static final String DIRECTORY = "/io/orchard/agents/zoo/models/";
    private static final int MAX_BYTES = 60 * 1024;
    private static final Set<String> INTERPOLATORS =
            Set.of("PositionInterpolator", "OrientationInterpolator", "ScalarInterpolator");
    private static final Pattern VRML_NUMBER = Pattern.compile("[-+]?[0-9.].*");

    /** What a controller relies on for one agent. */
    record Agent(String name, String file, List<String> joints, List<String> sensors,
                 Map<String, String> nestedIn) {

        @Override
        public String toString() {
            return name;
        }
    }

    static Stream<Agent> agents() {
        List<String> humanoid = List.of("Neck", "LeftShoulder", "LeftElbow", "RightShoulder",
                "RightElbow", "LeftHip", "LeftKnee", "RightHip", "RightKnee");
        Map<String, String> arms = Map.of("LeftElbow", "LeftShoulder",
                "RightElbow", "RightShoulder", "LeftKnee", "LeftHip", "RightKnee", "RightHip");
        return Stream.of(
                new Agent("Guppy", "Guppy.wrl", humanoid,
                        List.of("GuppyTSWalk", "GuppyTSGrasp"), arms),
                new Agent("Dwarf", "Dwarf.x3d", humanoid,
                        List.of("DwarfTSWalk", "DwarfTSGrasp"), arms),
                new Agent("Robot", "Robot.x3d",
                        List.of("Head", "LeftShoulder", "LeftClaw", "RightShoulder", "RightClaw",
                                "LeftHip", "LeftKnee", "RightHip", "RightKnee"),
                        List.of("RobotTSWalk", "RobotTSGrasp"),
                        Map.of("LeftClaw", "LeftShoulder", "RightClaw", "RightShoulder",
                                "LeftKnee", "LeftHip", "RightKnee", "RightHip")),
                new Agent("Bunny", "Bunny.x3d",
                        List.of("BunnyBody", "FrontLeftLeg", "FrontRightLeg", "BackLeftLeg",
                                "BackRightLeg", "Head", "LeftEar", "RightEar"),
                        List.of("BunnyTSWalk", "BunnyTSGrasp"),
                        Map.of("FrontLeftLeg", "BunnyBody", "FrontRightLeg", "BunnyBody",
                                "BackLeftLeg", "BunnyBody", "BackRightLeg", "BunnyBody",
                                "Head", "BunnyBody", "LeftEar", "Head", "RightEar", "Head")),
                new Agent("Roadrunner", "Roadrunner.x3d",
                        List.of("LeftHip", "LeftKnee", "LeftAnkle", "RightHip", "RightKnee",
                                "RightAnkle", "Neck1", "Neck2", "Neck3", "Neck4", "UpperBeak",
                                "LowerBeak"),
                        List.of("RoadrunnerTSWalk", "RoadrunnerTSGrasp", "RoadrunnerTSJump",
                                "RoadrunnerTSKneel"),
                        Map.of("LeftKnee", "LeftHip", "LeftAnkle", "LeftKnee",
                                "RightKnee", "RightHip", "RightAnkle", "RightKnee",
                                "Neck2", "Neck1", "Neck3", "Neck2", "Neck4", "Neck3",
                                "UpperBeak", "Neck4", "LowerBeak", "Neck4")));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("agents")
    void isSmallAndInItsFormat(Agent agent) {
        byte[] bytes = bytes(agent.file());
        String text = new String(bytes, StandardCharsets.UTF_8);
        assertThat(bytes.length).as("%s size", agent.file()).isLessThan(MAX_BYTES);
        if (agent.file().endsWith(".wrl")) {
            assertThat(text).startsWith("#VRML V2.0 utf8\n");
        } else {
            assertThat(text).startsWith("<?xml").contains("<!DOCTYPE X3D");
            Model model = parse(agent); // well-formed, header checked while parsing
            assertThat(model.defs()).isNotEmpty();
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("agents")
    void rootTransformIsNamedAfterTheAgentAndHoldsTheWholeBody(Agent agent) {
        Model model = parse(agent);
        Node root = model.defs().get(agent.name());
        assertThat(root).as("DEF %s", agent.name()).isNotNull();
        assertThat(root.type()).isEqualTo("Transform");
        assertThat(root.ancestors()).as("%s is a top-level node", agent.name()).isEmpty();
        assertThat(model.topLevelTypes().stream()
                .filter(type -> !INTERPOLATORS.contains(type) && !type.equals("TimeSensor")))
                .as("top-level nodes other than animations: only the root")
                .containsExactly("Transform");
        for (Node node : model.defs().values()) {
            if (node != root && (node.type().equals("Transform") || node.type().equals("Shape")
                    || node.type().equals("Group"))) {
                assertThat(node.ancestors()).as("%s is inside %s", node.def(), agent.name())
                        .contains(agent.name());
            }
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("agents")
    void everyJointIsADefTransformNestedAsASkeleton(Agent agent) {
        Model model = parse(agent);
        for (String joint : agent.joints()) {
            Node node = model.defs().get(joint);
            assertThat(node).as("joint %s", joint).isNotNull();
            assertThat(node.type()).as("joint %s", joint).isEqualTo("Transform");
            assertThat(node.ancestors()).as("joint %s is inside %s", joint, agent.name())
                    .contains(agent.name());
        }
        agent.nestedIn().forEach((joint, parent) ->
                assertThat(model.defs().get(joint).ancestors())
                        .as("%s is nested in %s", joint, parent).contains(parent));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("agents")
    void timeSensorsExistAndStayIdleUntilStarted(Agent agent) {
        Model model = parse(agent);
        for (String sensor : agent.sensors()) {
            Node node = model.defs().get(sensor);
            assertThat(node).as("TimeSensor %s", sensor).isNotNull();
            assertThat(node.type()).as(sensor).isEqualTo("TimeSensor");
            assertThat(single(node, "enabled")).as(sensor + " enabled").isEqualToIgnoringCase("true");
            assertThat(single(node, "loop")).as(sensor + " loop").isEqualToIgnoringCase("false");
            assertThat(number(node, "startTime")).as(sensor + " startTime").isZero();
            assertThat(number(node, "stopTime")).as(sensor + " stopTime").isZero();
            double cycle = number(node, "cycleInterval");
            if (sensor.endsWith("TSWalk")) {
                assertThat(cycle).as(sensor + " cycleInterval").isCloseTo(1.0, within(0.25));
            } else if (sensor.endsWith("TSGrasp")) {
                assertThat(cycle).as(sensor + " cycleInterval").isCloseTo(1.5, within(0.3));
            } else {
                assertThat(cycle).as(sensor + " cycleInterval").isPositive();
            }
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("agents")
    void everyAnimationDrivesJointsAndReturnsToTheNeutralPose(Agent agent) {
        Model model = parse(agent);
        for (String sensor : agent.sensors()) {
            List<String> interpolators = model.routes().stream()
                    .filter(r -> r.fromNode().equals(sensor))
                    .map(Route::toNode).toList();
            assertThat(interpolators).as("interpolators %s drives", sensor).isNotEmpty();
            Set<String> moved = new LinkedHashSet<>();
            for (String name : interpolators) {
                Node interpolator = model.defs().get(name);
                List<Route> out = model.routes().stream()
                        .filter(r -> r.fromNode().equals(name)).toList();
                assertThat(out).as("ROUTEs from %s", name).isNotEmpty();
                out.forEach(r -> moved.add(r.toNode()));
                checkNeutralAtBothEnds(interpolator);
            }
            assertThat(moved).as("what %s moves", sensor)
                    .isNotEmpty()
                    .doesNotContain(agent.name())
                    .allSatisfy(target -> {
                        assertThat(model.defs()).as("DEF %s", target).containsKey(target);
                        assertThat(model.defs().get(target).ancestors())
                                .as("%s is part of %s's body", target, agent.name())
                                .contains(agent.name());
                    });
        }
        assertThat(model.defs().values().stream()
                .filter(n -> n.type().equals("TimeSensor")).map(Node::def))
                .as("the TimeSensors")
                .containsExactlyInAnyOrderElementsOf(concat(agent.sensors(),
                        agent.name() + "TSMover"));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("agents")
    void everyRouteConnectsDefinedNodesWithMatchingFields(Agent agent) {
        Model model = parse(agent);
        assertThat(model.routes()).isNotEmpty();
        for (Route route : model.routes()) {
            Node from = model.defs().get(route.fromNode());
            Node to = model.defs().get(route.toNode());
            assertThat(from).as("%s: from-node", route).isNotNull();
            assertThat(to).as("%s: to-node", route).isNotNull();
            if (from.type().equals("TimeSensor")) {
                assertThat(route.fromField()).as(route.toString()).isEqualTo("fraction_changed");
                assertThat(INTERPOLATORS).as(route.toString()).contains(to.type());
                assertThat(route.toField()).as(route.toString()).isEqualTo("set_fraction");
            } else {
                assertThat(INTERPOLATORS).as(route.toString()).contains(from.type());
                assertThat(route.fromField()).as(route.toString()).isEqualTo("value_changed");
                assertThat(to.type()).as(route.toString()).isEqualTo("Transform");
                assertThat(route.toField()).as(route.toString()).isEqualTo(
                        from.type().equals("OrientationInterpolator")
                                ? "set_rotation" : "set_translation");
            }
        }
        assertThat(model.uses()).as("every USE names a DEF before it")
                .allSatisfy(use -> assertThat(model.defs()).containsKey(use));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("agents")
    void hasThePapersMovementNodes(Agent agent) {
        Model model = parse(agent);
        String name = agent.name();
        assertThat(model.defs().get(name + "Mover")).as(name + "Mover").isNotNull()
                .extracting(Node::type).isEqualTo("PositionInterpolator");
        assertThat(model.defs().get(name + "TSMover")).as(name + "TSMover").isNotNull()
                .extracting(Node::type).isEqualTo("TimeSensor");
        assertThat(model.routes()).contains(
                new Route(name + "TSMover", "fraction_changed", name + "Mover", "set_fraction"),
                new Route(name + "Mover", "value_changed", name, "set_translation"));
    }

    @Test
    void guppyHasTheNodesOfFigure5Verbatim() {
        String text = normalizedVrml(new String(bytes("Guppy.wrl"), StandardCharsets.UTF_8));
        assertThat(text)
                .startsWith("DEF Guppy Transform { children [")
                .contains(normalizedVrml(
                        "DEF GuppyMover PositionInterpolator { key [ 0.0 1.0 ] "
                                + "keyValue [ 0 0 0, 10 0 10 ] }"))
                .contains(normalizedVrml(
                        "DEF GuppyTSMover TimeSensor { cycleInterval 1.0 loop FALSE enabled FALSE }"))
                .contains("ROUTE GuppyTSMover.fraction_changed TO GuppyMover.set_fraction")
                .contains("ROUTE GuppyMover.value_changed TO Guppy.set_translation");
        Model model = parse(agents().filter(a -> a.name().equals("Guppy")).findFirst()
                .orElseThrow());
        assertThat(model.routes().stream().filter(r -> r.fromNode().contains("Mover")))
                .as("the movement ROUTEs").hasSize(2);
    }

    // ---- the neutral pose ---------------------------------------------------------------------

    private static void checkNeutralAtBothEnds(Node interpolator) {
        String name = interpolator.def();
        double[] key = numbers(interpolator, "key");
        double[] values = numbers(interpolator, "keyValue");
        int width = switch (interpolator.type()) {
            case "PositionInterpolator" -> 3;
            case "OrientationInterpolator" -> 4;
            default -> 1;
        };
        assertThat(key.length).as(name + " keys").isGreaterThanOrEqualTo(2);
        assertThat(values.length).as(name + " keyValue count").isEqualTo(key.length * width);
        assertThat(key[0]).as(name + " first key").isZero();
        assertThat(key[key.length - 1]).as(name + " last key").isEqualTo(1.0);
        for (int i = 1; i < key.length; i++) {
            assertThat(key[i]).as(name + " keys increase").isGreaterThan(key[i - 1]);
        }
        double[] first = Arrays.copyOfRange(values, 0, width);
        double[] last = Arrays.copyOfRange(values, values.length - width, values.length);
        if (width == 4) {
            assertThat(first[3]).as(name + " starts at the identity rotation").isZero();
            assertThat(last[3]).as(name + " ends at the identity rotation").isZero();
        } else {
            assertThat(last).as(name + " ends where it starts").containsExactly(first);
        }
    }

    // ---- a small reading of both encodings ----------------------------------------------------

    /** One DEF'd node: its type, the DEF names of the nodes around it, its simple fields. */
    record Node(String def, String type, List<String> ancestors,
                Map<String, List<String>> fields) {
    }

    record Route(String fromNode, String fromField, String toNode, String toField) {

        @Override
        public String toString() {
            return "ROUTE " + fromNode + "." + fromField + " TO " + toNode + "." + toField;
        }
    }

    /** What the checks need to know of a model file. */
    record Model(Map<String, Node> defs, List<Route> routes, List<String> uses,
                 List<String> topLevelTypes) {
    }

    private static Model parse(Agent agent) {
        byte[] bytes = bytes(agent.file());
        return agent.file().endsWith(".wrl")
                ? parseVrml(new String(bytes, StandardCharsets.UTF_8))
                : parseX3d(bytes, agent.file());
    }

    private static Model parseX3d(byte[] bytes, String file) {
        XMLInputFactory factory = XMLInputFactory.newDefaultFactory();
        factory.setProperty(XMLInputFactory.SUPPORT_DTD, false);
        factory.setProperty(XMLInputFactory.IS_SUPPORTING_EXTERNAL_ENTITIES, false);
        Map<String, Node> defs = new LinkedHashMap<>();
        List<Route> routes = new ArrayList<>();
        List<String> uses = new ArrayList<>();
        List<String> topLevel = new ArrayList<>();
        Deque<String> open = new ArrayDeque<>(); // element names
        Deque<String> defStack = new ArrayDeque<>(); // DEF names, "" for none
        boolean sawScene = false;
        try {
            XMLStreamReader xml = factory.createXMLStreamReader(new ByteArrayInputStream(bytes));
            while (xml.hasNext()) {
                int event = xml.next();
                if (event == XMLStreamConstants.END_ELEMENT) {
                    open.pop();
                    defStack.pop();
                    continue;
                }
                if (event != XMLStreamConstants.START_ELEMENT) {
                    continue;
                }
                String element = xml.getLocalName();
                if (open.isEmpty()) {
                    assertThat(element).as(file + " root element").isEqualTo("X3D");
                    assertThat(xml.getAttributeValue(null, "profile")).as(file + " profile")
                            .isEqualTo("Interchange");
                    assertThat(xml.getAttributeValue(null, "version")).as(file + " version")
                            .isEqualTo("3.3");
                }
                boolean inScene = open.contains("Scene");
                sawScene |= element.equals("Scene");
                String def = inScene ? xml.getAttributeValue(null, "DEF") : null;
                if (inScene) {
                    if (Objects.equals(open.peek(), "Scene") && !element.equals("ROUTE")) {
                        topLevel.add(element);
                    }
                    if (element.equals("ROUTE")) {
                        routes.add(new Route(xml.getAttributeValue(null, "fromNode"),
                                xml.getAttributeValue(null, "fromField"),
                                xml.getAttributeValue(null, "toNode"),
                                xml.getAttributeValue(null, "toField")));
                    }
                    String use = xml.getAttributeValue(null, "USE");
                    if (use != null) {
                        assertThat(defs).as(file + ": USE " + use + " after its DEF")
                                .containsKey(use);
                        uses.add(use);
                    }
                    if (def != null) {
                        Map<String, List<String>> fields = new LinkedHashMap<>();
                        for (int i = 0; i < xml.getAttributeCount(); i++) {
                            fields.put(xml.getAttributeLocalName(i), List.of(
                                    xml.getAttributeValue(i).trim().split("[\\s,]+")));
                        }
                        assertThat(defs).as(file + ": DEF " + def + " is unique")
                                .doesNotContainKey(def);
                        defs.put(def, new Node(def, element, ancestors(defStack), fields));
                    }
                }
                open.push(element);
                defStack.push(def == null ? "" : def);
            }
            xml.close();
        } catch (XMLStreamException e) {
            throw new AssertionError(file + " is not well-formed XML: " + e.getMessage(), e);
        }
        assertThat(sawScene).as(file + " has a Scene").isTrue();
        return new Model(defs, routes, uses, topLevel);
    }

    private static Model parseVrml(String text) {
        List<String> tokens = vrmlTokens(text);
        Map<String, Node> defs = new LinkedHashMap<>();
        List<Route> routes = new ArrayList<>();
        List<String> uses = new ArrayList<>();
        List<String> topLevel = new ArrayList<>();
        Deque<String> braces = new ArrayDeque<>(); // DEF name of each open brace, "" for none
        String pendingDef = null;
        for (int i = 0; i < tokens.size(); i++) {
            String token = tokens.get(i);
            switch (token) {
                case "DEF" -> {
                    String def = tokens.get(i + 1);
                    String type = tokens.get(i + 2);
                    assertThat(tokens.get(i + 3)).as("DEF " + def + " " + type + " {")
                            .isEqualTo("{");
                    assertThat(defs).as("DEF " + def + " is unique").doesNotContainKey(def);
                    defs.put(def, new Node(def, type, ancestors(braces),
                            vrmlFields(tokens, i + 4)));
                    pendingDef = def;
                    i++;
                }
                case "USE" -> {
                    String use = tokens.get(++i);
                    assertThat(defs).as("USE " + use + " after its DEF").containsKey(use);
                    uses.add(use);
                }
                case "ROUTE" -> {
                    String[] from = tokens.get(i + 1).split("\\.");
                    String[] to = tokens.get(i + 3).split("\\.");
                    assertThat(tokens.get(i + 2)).isEqualTo("TO");
                    routes.add(new Route(from[0], from[1], to[0], to[1]));
                    i += 3;
                }
                case "{" -> {
                    if (braces.isEmpty()) {
                        topLevel.add(tokens.get(i - 1));
                    }
                    braces.push(pendingDef == null ? "" : pendingDef);
                    pendingDef = null;
                }
                case "}" -> braces.pop();
                default -> { }
            }
        }
        assertThat(braces).as("balanced braces").isEmpty();
        return new Model(defs, routes, uses, topLevel);
    }

    /** VRML97 tokens: comments dropped, commas are white space, braces and brackets apart. */
    private static List<String> vrmlTokens(String text) {
        List<String> tokens = new ArrayList<>();
        int i = 0;
        int n = text.length();
        while (i < n) {
            char c = text.charAt(i);
            if (c == '#') {
                while (i < n && text.charAt(i) != '\n') {
                    i++;
                }
            } else if (Character.isWhitespace(c) || c == ',') {
                i++;
            } else if ("{}[]".indexOf(c) >= 0) {
                tokens.add(String.valueOf(c));
                i++;
            } else if (c == '"') {
                int j = i + 1;
                while (j < n && text.charAt(j) != '"') {
                    j += text.charAt(j) == '\\' ? 2 : 1;
                }
                tokens.add(text.substring(i, Math.min(n, j + 1)));
                i = j + 1;
            } else {
                int j = i;
                while (j < n && !Character.isWhitespace(text.charAt(j))
                        && "{}[]#,\"".indexOf(text.charAt(j)) < 0) {
                    j++;
                }
                tokens.add(text.substring(i, j));
                i = j;
            }
        }
        return tokens;
    }

    /** The fields of a node that holds no other node, from just after its opening brace. */
    private static Map<String, List<String>> vrmlFields(List<String> tokens, int start) {
        Map<String, List<String>> fields = new LinkedHashMap<>();
        String field = null;
        for (int i = start; i < tokens.size(); i++) {
            String token = tokens.get(i);
            if (token.equals("{")) {
                return Map.of(); // holds nodes: not needed by these checks
            }
            if (token.equals("}")) {
                break;
            }
            if (token.equals("[") || token.equals("]")) {
                continue;
            }
            boolean value = VRML_NUMBER.matcher(token).matches() || token.equals("TRUE")
                    || token.equals("FALSE");
            if (!value) {
                field = token;
                fields.put(field, new ArrayList<>());
            } else if (field != null) {
                fields.get(field).add(token);
            }
        }
        return fields;
    }

    /** Comments dropped, braces and brackets set apart, white space collapsed. */
    private static String normalizedVrml(String text) {
        return text.replaceAll("#[^\\n]*", " ")
                .replaceAll("([{}\\[\\]])", " $1 ")
                .replaceAll("\\s+", " ")
                .strip();
    }

    private static List<String> ancestors(Deque<String> stack) {
        return stack.stream().filter(name -> !name.isEmpty()).toList();
    }

    private static String single(Node node, String field) {
        List<String> values = node.fields().get(field);
        assertThat(values).as(node.def() + " field " + field).isNotNull().hasSize(1);
        return values.get(0);
    }

    private static double number(Node node, String field) {
        return Double.parseDouble(single(node, field));
    }

    private static double[] numbers(Node node, String field) {
        List<String> values = node.fields().get(field);
        assertThat(values).as(node.def() + " field " + field).isNotNull();
        return values.stream().mapToDouble(Double::parseDouble).toArray();
    }

    private static List<String> concat(List<String> list, String more) {
        List<String> all = new ArrayList<>(list);
        all.add(more);
        return all;
    }

    private static byte[] bytes(String file) {
        try (InputStream in = ModelConventionsTest.class.getResourceAsStream(DIRECTORY + file)) {
            assertThat(in).as("resource " + DIRECTORY + file).isNotNull();
            return in.readAllBytes();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
