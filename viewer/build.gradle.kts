plugins {
    `java-library`
    `maven-publish`
    application
}

apply(from = rootProject.file("gradle/java-conventions.gradle.kts"))
apply(from = rootProject.file("gradle/publish-conventions.gradle.kts"))

group = "io.orchard"
version = "0.1.0-SNAPSHOT"
description = "The jMonkeyEngine viewer: renders the world and drives agent models from protocol messages."

// The run task's SLF4J provider, on its class path alone: the published module leaves the choice of
// logging to the program that uses it, as under Maven, where the launcher (examples) brings Logback.
val runLogging by configurations.creating

dependencies {
    api(project(":protocol"))
    implementation(project(":cli"))
    // The viewer is a jME application made of app states, so jME's core types are part of its API.
    api(libs.jme3.core)
    implementation(libs.jme3.desktop)
    implementation(libs.jme3.lwjgl3)
    implementation(libs.jme3.plugins)
    implementation(libs.slf4j.api)
    // jME logs to java.util.logging; the viewer sends it into SLF4J, so there is one log.
    implementation(libs.jul.to.slf4j)
    // ViewerMain.command() hands its picocli CommandLine to launchers.
    api(libs.picocli)

    runLogging(libs.logback.classic)

    // The viewer is tested against a real server, which it never depends on otherwise.
    testImplementation(project(":server"))
    testImplementation(libs.logback.classic)
    testImplementation(libs.junit.jupiter)
    testImplementation(libs.assertj.core)
    testRuntimeOnly(libs.junit.platform.launcher)
}

application {
    mainClass = "io.orchard.viewer.ViewerMain"
}

tasks.named<JavaExec>("run") {
    classpath += runLogging
    // In the directory gradle was started from, as ./orchard runs, so that relative paths in the
    // arguments (--replay, --out) mean what they say, not a path inside viewer/.
    workingDir = gradle.startParameter.currentDir
}
