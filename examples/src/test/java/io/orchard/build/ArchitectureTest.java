package io.orchard.build;

import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.noClasses;
import static com.tngtech.archunit.library.dependencies.SlicesRuleDefinition.slices;

import com.tngtech.archunit.core.domain.JavaClass;
import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.importer.ClassFileImporter;
import com.tngtech.archunit.core.importer.ImportOption;
import com.tngtech.archunit.lang.ArchRule;
import com.tngtech.archunit.library.dependencies.SliceAssignment;
import com.tngtech.archunit.library.dependencies.SliceIdentifier;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;

/**
 * The directions the modules and packages depend in, read from the compiled classes of every
 * module: protocol and cli (the command lines' shared converters and errors) under everything,
 * knowing nothing of each other; server, agents and viewer beside each other, examples on top;
 * Netty and JTS only in the server (JTS only in its world), jMonkeyEngine only in the viewer; no
 * cycle between packages, and none between the classes of the server's simulation.
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
                            "io.orchard.agents..", "io.orchard.viewer..", "io.orchard.examples.."));
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
        void nettyOnlyInTheServersNetwork() {
            check(noClasses().that().resideOutsideOfPackage("io.orchard.server.net..")
                    .should().dependOnClassesThat().resideInAPackage("io.netty.."));
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
