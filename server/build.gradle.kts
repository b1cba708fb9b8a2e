plugins {
    `java-library`
    application
}

apply(from = rootProject.file("gradle/java-conventions.gradle.kts"))

group = "io.orchard"
version = "0.1.0-SNAPSHOT"
description = "The world server: the 2.5D world model on JTS, the simulation and the Netty network layer."

dependencies {
    api(project(":protocol"))
    implementation(libs.netty.handler)
    implementation(libs.netty.codec.base)
    implementation(libs.jts.core)
    implementation(libs.slf4j.api)
    // ServerMain.command() hands its picocli CommandLine to launchers.
    api(libs.picocli)

    testImplementation(libs.logback.classic)
    testImplementation(libs.jazzer.junit)
    testImplementation(libs.jmh.core)
    testAnnotationProcessor(libs.jmh.generator.annprocess)
    testImplementation(platform(libs.junit.bom))
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
    // The server reads commands from its console.
    standardInput = System.`in`
}

// Stamp the build's version into the version resource, as Maven's resource filtering does.
tasks.processResources {
    filesMatching("**/*version.properties") {
        expand("project" to mapOf("version" to project.version))
    }
}
