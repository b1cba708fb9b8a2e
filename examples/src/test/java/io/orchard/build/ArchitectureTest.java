package io.orchard.build;

import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.noClasses;
import static com.tngtech.archunit.library.dependencies.SlicesRuleDefinition.slices;

import com.tngtech.archunit.base.DescribedPredicate;
import com.tngtech.archunit.core.domain.JavaClass;
import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.importer.ClassFileImporter;
import com.tngtech.archunit.core.importer.ImportOption;
import com.tngtech.archunit.lang.ArchRule;
import com.tngtech.archunit.library.dependencies.SliceAssignment;
import com.tngtech.archunit.library.dependencies.SliceIdentifier;
import io.orchard.server.WebFrontEnd;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;

/**
 * The directions the modules and packages depend in, read from the compiled classes of every
 * module: protocol and cli (the command lines' shared converters and errors) under everything,
 * knowing nothing of each other; server, agents and viewer beside each other, the web viewer on the
 * server, the cluster on the server, examples on top; Netty only in the server's network and the web
 * viewer's HTTP side, JTS only in the server's world, jMonkeyEngine only in the viewer, Pekko only in
 * the cluster; no cycle between packages, and none between the classes of the server's simulation.
 */
class ArchitectureTest {

    private static JavaClasses orchard;

    @BeforeAll
    static void importTheClasses() {
        orchard = new ClassFileImporter()
                .withImportOption(ImportOption.Predefined.DO_NOT_INCLUDE_TESTS)
                .importPackages("io.orchard");
    }

    private static void check(ArchRule rule) {
        rule.check(orchard);
    }

    @Nested
    class Modules {

        @Test
        void protocolDependsOnNoOtherModule() {
            check(noClasses().that().resideInAPackage("io.orchard.protocol..")
                    .should().dependOnClassesThat().resideInAnyPackage("io.orchard.cli..", "io.orchard.server..",
                            "io.orchard.agents..", "io.orchard.viewer..", "io.orchard.cluster..",
                            "io.orchard.examples.."));
        }

        @Test
        void cliDependsOnNoOtherModule() {
            check(noClasses().that().resideInAPackage("io.orchard.cli..")
                    .should().dependOnClassesThat().resideInAnyPackage("io.orchard.protocol..", "io.orchard.server..",
                            "io.orchard.agents..", "io.orchard.viewer..", "io.orchard.examples.."));
        }

        @Test
        void cliDependsOnPicocliAlone() {
            check(noClasses().that().resideInAPackage("io.orchard.cli..")
                    .should().dependOnClassesThat().resideInAnyPackage("tools.jackson..", "io.netty..",
                            "org.locationtech..", "com.jme3..", "org.slf4j.."));
        }

        @Test
        void protocolDependsOnJacksonAlone() {
            check(noClasses().that().resideInAPackage("io.orchard.protocol..")
                    .should().dependOnClassesThat().resideInAnyPackage("io.netty..", "org.locationtech..",
                            "com.jme3..", "org.slf4j..", "picocli.."));
        }

        @Test
        void serverAgentsAndViewerDoNotKnowEachOther() {
            check(noClasses().that().resideInAPackage("io.orchard.server..")
                    .should().dependOnClassesThat().resideInAnyPackage("io.orchard.agents..", "io.orchard.viewer..",
                            "io.orchard.examples.."));
            check(noClasses().that().resideInAPackage("io.orchard.agents..")
                    .should().dependOnClassesThat().resideInAnyPackage("io.orchard.server..", "io.orchard.viewer..",
                            "io.orchard.examples.."));
            check(noClasses().that().resideInAPackage("io.orchard.viewer..")
                    .should().dependOnClassesThat().resideInAnyPackage("io.orchard.server..", "io.orchard.agents..",
                            "io.orchard.examples.."));
        }

        @Test
        void nettyOnlyInTheServersNetworkAndTheWebViewer() {
            check(noClasses().that().resideOutsideOfPackages("io.orchard.server.net..", "io.orchard.web")
                    .should().dependOnClassesThat().resideInAPackage("io.netty.."));
        }

        /**
         * The web viewer is the server's other network side, an HTTP port that serves a page and
         * relays its WebSocket: it takes Netty's transport, buffers, HTTP and WebSocket codec and the
         * line framing, and nothing else of Netty (no other protocol, no native transport).
         */
        @Test
        void theWebViewerUsesNettyForHttpWebSocketsAndLinesAlone() {
            check(noClasses().that().resideInAPackage("io.orchard.web")
                    .should().dependOnClassesThat(JavaClass.Predicates.resideInAPackage("io.netty..")
                            .and(DescribedPredicate.not(JavaClass.Predicates.resideInAnyPackage("io.netty.bootstrap",
                                    "io.netty.buffer", "io.netty.channel", "io.netty.channel.nio",
                                    "io.netty.channel.socket", "io.netty.channel.socket.nio",
                                    "io.netty.handler.codec", "io.netty.handler.codec.http",
                                    "io.netty.handler.codec.http.websocketx", "io.netty.util",
                                    "io.netty.util.concurrent")))));
        }

        /**
         * The web viewer knows of the server only the interface it provides, and speaks to the game
         * over the protocol like any client; nothing depends on it (the server finds it by
         * ServiceLoader, the launcher has it on its class path).
         */
        @Test
        void theWebViewerKnowsTheServerByItsFrontEndAloneAndNothingKnowsIt() {
            check(noClasses().that().resideInAPackage("io.orchard.web")
                    .should().dependOnClassesThat(JavaClass.Predicates.resideInAPackage("io.orchard.server..")
                            .and(DescribedPredicate.not(JavaClass.Predicates.belongToAnyOf(WebFrontEnd.class)))));
            check(noClasses().that().resideInAPackage("io.orchard.web")
                    .should().dependOnClassesThat().resideInAnyPackage("io.orchard.agents..", "io.orchard.viewer..",
                            "io.orchard.examples..", "org.locationtech..", "com.jme3.."));
            check(noClasses().that().resideOutsideOfPackage("io.orchard.web")
                    .should().dependOnClassesThat().resideInAPackage("io.orchard.web"));
        }

        /**
         * The cluster runs the server's rules for parcels of one world and the server's front end
         * on each node: it sits on the server and the protocol, and nothing but the launcher knows it.
         */
        @Test
        void theClusterSitsOnTheServerAndNothingKnowsIt() {
            check(noClasses().that().resideInAPackage("io.orchard.cluster..")
                    .should().dependOnClassesThat().resideInAnyPackage("io.orchard.agents..", "io.orchard.viewer..",
                            "io.orchard.web..", "io.orchard.examples..", "com.jme3.."));
            check(noClasses().that().resideOutsideOfPackages("io.orchard.cluster..", "io.orchard.examples..")
                    .should().dependOnClassesThat().resideInAPackage("io.orchard.cluster.."));
        }

        @Test
        void pekkoOnlyInTheCluster() {
            check(noClasses().that().resideOutsideOfPackage("io.orchard.cluster..")
                    .should().dependOnClassesThat().resideInAnyPackage("org.apache.pekko..", "scala.."));
        }

        @Test
        void jtsOnlyInTheServersWorld() {
            check(noClasses().that().resideOutsideOfPackage("io.orchard.server.world..")
                    .should().dependOnClassesThat().resideInAPackage("org.locationtech.jts.."));
        }

        @Test
        void jMonkeyEngineOnlyInTheViewer() {
            check(noClasses().that().resideOutsideOfPackage("io.orchard.viewer..")
                    .should().dependOnClassesThat().resideInAPackage("com.jme3.."));
        }
    }

    @Nested
    class Cycles {

        @Test
        void noCycleBetweenTheModules() {
            check(slices().matching("io.orchard.(*)..").should().beFreeOfCycles());
        }

        @Test
        void noCycleBetweenThePackagesOfAModule() {
            check(slices().matching("io.orchard.(*).(*)..").should().beFreeOfCycles());
        }

        @Test
        void theSimulationsDependOneWay() {
            check(slices().assignedFrom(new TopLevelClassesOf("io.orchard.server.sim")).should().beFreeOfCycles());
        }

        @Test
        void nothingInTheSimulationPackageCallsBackIntoSimulation() {
            check(noClasses().that().resideInAPackage("io.orchard.server.sim")
                    .and().doNotHaveSimpleName("Simulation").and().doNotHaveSimpleName("TickLoop")
                    .and().areNotNestedClasses()
                    .should().dependOnClassesThat().haveFullyQualifiedName("io.orchard.server.sim.Simulation"));
        }
    }

    /** Each top-level class of one package a slice of its own, with its nested classes in it. */
    private record TopLevelClassesOf(String packageName) implements SliceAssignment {

        @Override
        public SliceIdentifier getIdentifierOf(JavaClass javaClass) {
            if (!javaClass.getPackageName().equals(packageName)) {
                return SliceIdentifier.ignore();
            }
            String name = javaClass.getName();
            int nested = name.indexOf('$');
            return SliceIdentifier.of(nested < 0 ? name : name.substring(0, nested));
        }

        @Override
        public String getDescription() {
            return "the top-level classes of " + packageName;
        }
    }
}
