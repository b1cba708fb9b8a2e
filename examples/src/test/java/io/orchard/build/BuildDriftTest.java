package io.orchard.build;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import io.orchard.build.VersionCatalog.Library;
import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The Gradle build (settings.gradle.kts, gradle/libs.versions.toml, the convention scripts under
 * gradle/, each module's build.gradle.kts) must say what the Maven build (the poms) says: modules,
 * versions, dependencies and their scopes, kinds of module, BOM imports, compiler, test JVM,
 * Javadoc and publication settings, main classes and run tasks. The tests on the repository's own
 * files fail when the two drift apart; the nested tests drift a copy of those files on purpose
 * and show that each check then reports the drift.
 */
class BuildDriftTest {

    /** Libraries the examples module surely has on its test classpath, so the resolved-version check sees some. */
    private static final List<String> SURELY_RESOLVED = List.of("jackson-databind", "netty-handler", "jts-core",
            "jme3-core", "slf4j-api", "logback-classic", "junit-jupiter", "assertj-core");

    private static Path root;
    private static MavenBuild maven;
    private static GradleBuild gradle;

    @BeforeAll
    static void readBothBuilds() throws IOException {
        root = repositoryRoot();
        maven = MavenBuild.read(root);
        gradle = GradleBuild.read(root);
    }

    @Test
    void settingsIncludeExactlyThePomModules() {
        assertThat(maven.modules()).as("<modules> of pom.xml").isNotEmpty();
        assertThat(BuildChecks.modules(maven, gradle))
                .as("modules of settings.gradle.kts against <modules> of pom.xml")
                .isEmpty();
    }

    @Test
    void catalogVersionsEqualThePomProperties() {
        assertThat(BuildChecks.versions(maven, gradle.catalog()))
                .as("[versions] of gradle/libs.versions.toml against <properties> of pom.xml")
                .isEmpty();
    }

    @Test
    void catalogVersionsEqualTheVersionsMavenResolves() {
        ResolvedClasspath classpath = ResolvedClasspath.current();
        List<String> onClasspath = gradle.catalog().libraries().values().stream()
                .filter(library -> classpath.versionOf(library.group(), library.artifact()).isPresent())
                .map(Library::alias)
                .toList();
        assertThat(onClasspath)
                .as("catalog libraries found on the test classpath %s", System.getProperty("java.class.path"))
                .containsAll(SURELY_RESOLVED);

        assertThat(BuildChecks.resolvedVersions(gradle.catalog(), classpath))
                .as("[libraries] of gradle/libs.versions.toml against the jars on the test classpath")
                .isEmpty();
    }

    @Test
    void moduleDependenciesOfEachBuildScriptEqualThePom() {
        assertThat(BuildChecks.moduleDependencies(maven, gradle))
                .as("project(...) dependencies of each build.gradle.kts against io.orchard dependencies of its pom.xml")
                .isEmpty();
    }

    @Test
    void libraryDependenciesOfEachBuildScriptEqualThePom() {
        assertThat(BuildChecks.libraryDependencies(maven, gradle))
                .as("library dependencies of each build.gradle.kts against those of its pom.xml and the root pom.xml")
                .isEmpty();
    }

    @Test
    void groupAndVersionOfEachBuildScriptEqualThePom() {
        assertThat(BuildChecks.coordinates(maven, gradle))
                .as("group, artifact and version of each build.gradle.kts against those of its pom.xml")
                .isEmpty();
    }

    @Test
    void eachModuleBuildsTheSameKindOfThingInBothBuilds() {
        assertThat(maven.builds().values()).extracting(ModuleBuild::kind)
                .contains(ModuleBuild.Kind.LIBRARY, ModuleBuild.Kind.PLATFORM, ModuleBuild.Kind.PROGRAM);
        assertThat(BuildChecks.kinds(maven, gradle))
                .as("plugins of each build.gradle.kts against packaging and deployment of its pom.xml")
                .isEmpty();
    }

    @Test
    void conventionScriptsSetWhatTheRootPomSets() {
        assertThat(maven.settings()).containsKeys("BOM imports", "compiler release", "compiler arguments",
                "test JVM arguments", "Javadoc doclint");
        assertThat(BuildChecks.settings(maven, gradle))
                .as("gradle/*-conventions.gradle.kts against the root pom.xml")
                .isEmpty();
    }

    @Test
    void eachModuleSetsWhatItsPomSets() {
        assertThat(maven.builds().get("protocol").settings()).containsKeys("Automatic-Module-Name", "sources jar",
                "Javadoc jar", "pom licence", "pom scm");
        assertThat(BuildChecks.moduleSettings(maven, gradle))
                .as("publication, jars and main class of each build.gradle.kts against its pom.xml")
                .isEmpty();
    }

    @Test
    void runTasksRunAMainClassInTheCallersDirectoryWithAnSlf4jProvider() {
        assertThat(gradle.builds().values()).filteredOn(build -> build.settings().containsKey("main class"))
                .extracting(ModuleBuild::name)
                .contains("examples", "server", "viewer");
        assertThat(BuildChecks.runTasks(gradle, root))
                .as("the run task of each build.gradle.kts with the application plugin")
                .isEmpty();
    }

    @Test
    void bomManagesEveryPublishedLibraryAndNothingElse() {
        List<String> libraries = maven.builds().values().stream()
                .filter(build -> build.kind() == ModuleBuild.Kind.LIBRARY)
                .map(ModuleBuild::name)
                .sorted()
                .toList();
        assertThat(maven.builds().get("bom").settings().get("managed modules"))
                .as("the modules bom/pom.xml manages: every published library of the root pom's <modules>")
                .isEqualTo(String.join(", ", libraries));
    }

    @Test
    void classpathReaderFindsJarsInMavenRepositoryAndGradleCacheLayouts() {
        ResolvedClasspath classpath = ResolvedClasspath.of(String.join(File.pathSeparator,
                "/home/dev/.m2/repository/org/locationtech/jts/jts-core/1.19.0/jts-core-1.19.0.jar",
                "/home/dev/.gradle/caches/modules-2/files-2.1/org.slf4j/slf4j-api/2.0.9/"
                        + "7cf2726fdcfbc8610f9a71fb3ed639871f315340/slf4j-api-2.0.9.jar",
                "/home/dev/orchard/protocol/target/classes"));

        assertThat(classpath.versionOf("org.locationtech.jts", "jts-core")).contains("1.19.0");
        assertThat(classpath.versionOf("org.slf4j", "slf4j-api")).contains("2.0.9");
        assertThat(classpath.versionOf("io.netty", "netty-handler")).isEmpty();
    }

    /** Each check, fed a copy of the build files with one deliberate drift, reports exactly that drift. */
    @Nested
    class WhenTheBuildsDrift {

        @TempDir
        Path copy;

        @BeforeEach
        void copyBuildFiles() throws IOException {
            List<String> files = new ArrayList<>(List.of("pom.xml", "settings.gradle.kts", "gradle/libs.versions.toml",
                    GradleBuild.JAVA_CONVENTIONS, GradleBuild.PUBLISH_CONVENTIONS));
            for (String module : maven.modules()) {
                files.add(module + "/pom.xml");
                files.add(module + "/build.gradle.kts");
            }
            for (String file : files) {
                Path target = copy.resolve(file);
                Files.createDirectories(target.getParent());
                Files.copy(root.resolve(file), target);
            }
        }

        @Test
        void moduleCheckReportsAModuleLeftOutOfSettings() throws IOException {
            Check check = dir -> BuildChecks.modules(MavenBuild.read(dir), GradleBuild.read(dir));

            assertThat(driftsAfterEdit(check, "settings.gradle.kts", "\"agents\", ", ""))
                    .containsExactly(new Drift("module agents", "present", "absent"));
        }

        @Test
        void versionCheckReportsACatalogVersionThatDiffersFromItsProperty() throws IOException {
            Check check = dir -> BuildChecks.versions(MavenBuild.read(dir), GradleBuild.read(dir).catalog());

            assertThat(driftsAfterEdit(check, "gradle/libs.versions.toml", "jts = \"" + catalogVersion("jts") + "\"",
                    "jts = \"0.0.1-drifted\""))
                    .containsExactly(new Drift("version jts (property jts.version)",
                            maven.properties().get("jts.version"), "0.0.1-drifted"));
        }

        @Test
        void versionCheckReportsACatalogVersionWithoutProperty() throws IOException {
            Check check = dir -> BuildChecks.versions(MavenBuild.read(dir), GradleBuild.read(dir).catalog());

            assertThat(driftsAfterEdit(check, "gradle/libs.versions.toml", "[versions]\n",
                    "[versions]\nguava = \"33.4.0-jre\"\n"))
                    .containsExactly(new Drift("version guava",
                            "no property mapped to it in BuildChecks.VERSION_PROPERTIES", "33.4.0-jre"));
        }

        @Test
        void versionCheckReportsAVersionPropertyWithoutCatalogVersion() throws IOException {
            Check check = dir -> BuildChecks.versions(MavenBuild.read(dir), GradleBuild.read(dir).catalog());

            assertThat(driftsAfterEdit(check, "pom.xml", "<properties>",
                    "<properties>\n    <guava.version>33.4.0-jre</guava.version>"))
                    .containsExactly(new Drift("property guava.version",
                            "33.4.0-jre", "no catalog version mapped to it in BuildChecks.VERSION_PROPERTIES"));
        }

        @Test
        void resolvedVersionCheckReportsACatalogVersionMavenDoesNotResolve() throws IOException {
            ResolvedClasspath classpath = ResolvedClasspath.current();
            Check check = dir -> BuildChecks.resolvedVersions(GradleBuild.read(dir).catalog(), classpath);

            assertThat(driftsAfterEdit(check, "gradle/libs.versions.toml", "jts = \"" + catalogVersion("jts") + "\"",
                    "jts = \"0.0.1-drifted\""))
                    .containsExactly(new Drift("resolved version of library jts-core (org.locationtech.jts:jts-core)",
                            classpath.versionOf("org.locationtech.jts", "jts-core").orElseThrow(), "0.0.1-drifted"));
        }

        @Test
        void moduleDependencyCheckReportsAModuleDependencyInAnotherScope() throws IOException {
            Check check = dir -> BuildChecks.moduleDependencies(MavenBuild.read(dir), GradleBuild.read(dir));

            assertThat(driftsAfterEdit(check, "agents/build.gradle.kts", "testImplementation(project(\":server\"))",
                    "implementation(project(\":server\"))"))
                    .containsExactly(new Drift("agents dependency on module server", "test", "compile"));
        }

        @Test
        void libraryDependencyCheckReportsALibraryMissingFromABuildScript() throws IOException {
            Check check = dir -> BuildChecks.libraryDependencies(MavenBuild.read(dir), GradleBuild.read(dir));

            assertThat(driftsAfterEdit(check, "server/build.gradle.kts", "implementation(libs.jts.core)", ""))
                    .containsExactly(new Drift("server dependency on library org.locationtech.jts:jts-core",
                            "compile", "absent"));
        }

        @Test
        void libraryDependencyCheckReportsARuntimeOnlyDependencyThatIsCompileScopeInMaven() throws IOException {
            Check check = dir -> BuildChecks.libraryDependencies(MavenBuild.read(dir), GradleBuild.read(dir));

            assertThat(driftsAfterEdit(check, "server/build.gradle.kts", "implementation(libs.jts.core)",
                    "runtimeOnly(libs.jts.core)"))
                    .containsExactly(new Drift("server dependency on library org.locationtech.jts:jts-core",
                            "compile", "runtime"));
        }

        @Test
        void kindCheckReportsALibraryThatGradleDoesNotPublish() throws IOException {
            Check check = dir -> BuildChecks.kinds(MavenBuild.read(dir), GradleBuild.read(dir));

            assertThat(driftsAfterEdit(check, "agents/build.gradle.kts", "    `maven-publish`\n", ""))
                    .containsExactly(new Drift("agents kind", "library", "program"));
        }

        @Test
        void settingsCheckReportsABomImportMissingFromTheConventions() throws IOException {
            Check check = dir -> BuildChecks.settings(MavenBuild.read(dir), GradleBuild.read(dir));
            String imports = maven.settings().get("BOM imports");

            assertThat(driftsAfterEdit(check, GradleBuild.JAVA_CONVENTIONS, "\"netty-bom\", ", ""))
                    .containsExactly(new Drift("BOM imports", imports,
                            imports.replace("io.netty:netty-bom, ", "")));
        }

        @Test
        void settingsCheckReportsATestHeapThatDiffers() throws IOException {
            Check check = dir -> BuildChecks.settings(MavenBuild.read(dir), GradleBuild.read(dir));
            String heap = maven.settings().get("test JVM arguments");

            assertThat(driftsAfterEdit(check, GradleBuild.JAVA_CONVENTIONS, "maxHeapSize = \"",
                    "maxHeapSize = \"1"))
                    .containsExactly(new Drift("test JVM arguments", heap, heap.replace("-Xmx", "-Xmx1")));
        }

        @Test
        void moduleSettingsCheckReportsALicenceThatDiffers() throws IOException {
            Check check = dir -> BuildChecks.moduleSettings(MavenBuild.read(dir), GradleBuild.read(dir));

            List<Drift> drifts = driftsAfterEdit(check, GradleBuild.PUBLISH_CONVENTIONS,
                    "name.set(\"Apache-2.0\")", "name.set(\"MIT\")");

            assertThat(drifts).extracting(Drift::item)
                    .containsExactlyInAnyOrder("agents pom licence", "bom pom licence", "cli pom licence",
                            "cluster pom licence", "protocol pom licence", "server pom licence", "viewer pom licence",
                            "web pom licence");
            assertThat(drifts).extracting(Drift::gradle).allMatch(licence -> licence.startsWith("MIT "));
        }

        @Test
        void moduleSettingsCheckReportsAnExclusionOnlyOneBuildMakes() throws IOException {
            Check check = dir -> BuildChecks.moduleSettings(MavenBuild.read(dir), GradleBuild.read(dir));

            assertThat(driftsAfterEdit(check, "agents/build.gradle.kts",
                    "        exclude(group = \"tools.jackson.dataformat\", module = \"jackson-dataformat-yaml\")\n", ""))
                    .containsExactly(new Drift("agents exclusions of com.networknt:json-schema-validator",
                            "tools.jackson.dataformat:jackson-dataformat-yaml", Drift.ABSENT));
        }

        @Test
        void moduleSettingsCheckReportsAModuleTheBomLeavesOut() throws IOException {
            Check check = dir -> BuildChecks.moduleSettings(MavenBuild.read(dir), GradleBuild.read(dir));

            assertThat(driftsAfterEdit(check, "bom/build.gradle.kts", "        api(project(\":viewer\"))\n", ""))
                    .containsExactly(new Drift("bom managed modules", "agents, cli, cluster, protocol, server, viewer, web",
                            "agents, cli, cluster, protocol, server, web"));
        }

        @Test
        void runTaskCheckReportsARunInTheModulesFolderWithoutLogging() throws IOException {
            Check check = dir -> BuildChecks.runTasks(GradleBuild.read(dir), root);

            edit("viewer/build.gradle.kts", "    classpath += runLogging\n", "");
            assertThat(driftsAfterEdit(check, "viewer/build.gradle.kts",
                    "    workingDir = " + GradleBuild.CALLERS_DIRECTORY + "\n", ""))
                    .containsExactly(new Drift("viewer run working directory", GradleBuild.CALLERS_DIRECTORY,
                            "the module's directory"));
            assertThat(check.on(copy)).contains(new Drift("viewer run SLF4J provider",
                    "ch.qos.logback:logback-classic", "absent"));
        }

        @Test
        void runTaskCheckReportsAMainClassThatDoesNotExist() throws IOException {
            Check check = dir -> BuildChecks.runTasks(GradleBuild.read(dir), root);

            assertThat(driftsAfterEdit(check, "server/build.gradle.kts", "io.orchard.server.ServerMain",
                    "io.orchard.server.Gone"))
                    .containsExactly(new Drift("server run main class", "a class of src/main/java",
                            "io.orchard.server.Gone"));
        }

        @Test
        void coordinateCheckReportsAModuleVersionThatDiffers() throws IOException {
            Check check = dir -> BuildChecks.coordinates(MavenBuild.read(dir), GradleBuild.read(dir));
            String scriptVersion = gradle.builds().get("viewer").version();

            assertThat(driftsAfterEdit(check, "viewer/build.gradle.kts", "version = \"" + scriptVersion + "\"",
                    "version = \"9.9.9\""))
                    .containsExactly(new Drift("viewer version", maven.builds().get("viewer").version(), "9.9.9"));
        }

        @Test
        void gradleReaderRejectsADependencyItCannotCompare() throws IOException {
            edit("server/build.gradle.kts", "implementation(libs.jts.core)", "implementation(files(\"lib/jts.jar\"))");

            assertThatThrownBy(() -> GradleBuild.read(copy))
                    .isInstanceOf(IllegalArgumentException.class)
                    .hasMessageContaining("implementation(files(\"lib/jts.jar\"))");
        }

        @Test
        void mavenReaderRejectsAPomWithADoctype() throws IOException {
            edit("pom.xml", "<project ",
                    "<!DOCTYPE project [<!ENTITY home SYSTEM \"file:///etc/hostname\">]>\n<project ");

            assertThatThrownBy(() -> MavenBuild.read(copy))
                    .isInstanceOf(IllegalArgumentException.class)
                    .hasMessageContaining("without DOCTYPE");
        }

        /**
         * The drifts {@code check} reports on the copy once {@code from} is replaced by {@code to} in
         * {@code file}, leaving out those it reported before: a drift of the repository's own files
         * is the other tests' to report.
         */
        private List<Drift> driftsAfterEdit(Check check, String file, String from, String to) throws IOException {
            List<Drift> before = check.on(copy);
            edit(file, from, to);
            List<Drift> after = new ArrayList<>(check.on(copy));
            after.removeAll(before);
            return after;
        }

        /** Replaces {@code from} by {@code to} in the copy of {@code file}, which must contain it. */
        private void edit(String file, String from, String to) throws IOException {
            Path path = copy.resolve(file);
            String text = Files.readString(path);
            assertThat(text).as("copy of %s to drift", file).contains(from);
            Files.writeString(path, text.replace(from, to));
        }

        private String catalogVersion(String key) {
            return gradle.catalog().versions().get(key);
        }
    }

    /** One of the {@link BuildChecks}, run on the build files under a root directory. */
    @FunctionalInterface
    interface Check {
        List<Drift> on(Path root) throws IOException;
    }

    /** The directory holding both pom.xml and settings.gradle.kts: the working directory or one above it. */
    static Path repositoryRoot() {
        Path start = Path.of("").toAbsolutePath();
        for (Path dir = start; dir != null; dir = dir.getParent()) {
            if (Files.isRegularFile(dir.resolve("pom.xml"))
                    && Files.isRegularFile(dir.resolve("settings.gradle.kts"))) {
                return dir;
            }
        }
        throw new IllegalStateException(
                "expected pom.xml and settings.gradle.kts in " + start + " or a directory above it");
    }
}
