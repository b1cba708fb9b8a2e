plugins {
    `java-library`
    `maven-publish`
    application
}

apply(from = rootProject.file("gradle/java-conventions.gradle.kts"))
apply(from = rootProject.file("gradle/publish-conventions.gradle.kts"))

group = "io.orchard"
version = "0.1.0-SNAPSHOT"
description = "The world server: the 2.5D world model on JTS, the simulation and the Netty network layer."

// The run task's SLF4J provider, on its class path alone: the published module leaves the choice of
// logging to the program that uses it, as under Maven, where the launcher (examples) brings Logback.
val runLogging by configurations.creating

dependencies {
    api(project(":protocol"))
    implementation(project(":cli"))
    implementation(libs.netty.handler)
    implementation(libs.netty.codec.base)
    implementation(libs.jts.core)
    implementation(libs.slf4j.api)
    // ServerMain.command() hands its picocli CommandLine to launchers.
    api(libs.picocli)

    runLogging(libs.logback.classic)

    testImplementation(libs.logback.classic)
    testImplementation(libs.jazzer.junit)
    testImplementation(libs.jmh.core)
    testAnnotationProcessor(libs.jmh.generator.annprocess)
    testImplementation(libs.junit.jupiter)
    testImplementation(libs.assertj.core)
    testRuntimeOnly(libs.junit.platform.launcher)
}

// The JMH benchmarks compile with the tests so that they cannot rot (see docs/benchmarks.md).
sourceSets {
    test {
        java.srcDir("src/jmh/java")
    }
}

application {
    mainClass = "io.orchard.server.ServerMain"
}

tasks.named<JavaExec>("run") {
    classpath += runLogging
    // In the directory gradle was started from, as ./orchard runs, so that relative paths in the
    // arguments (--record, --resume, --scenario) mean what they say, not a path inside server/.
    workingDir = gradle.startParameter.currentDir
    // The server reads commands from its console.
    standardInput = System.`in`
}

// Stamp the build's version into the version resource, as Maven's resource filtering does.
tasks.processResources {
    filesMatching("**/*version.properties") {
        expand("project" to mapOf("version" to project.version))
    }
}
