plugins {
    application
}

apply(from = rootProject.file("gradle/java-conventions.gradle.kts"))

group = "io.orchard"
version = "0.1.0-SNAPSHOT"
description = "Runnable programs: the orchard launcher, the demo, embedding, a first agent and tournaments."

dependencies {
    implementation(project(":protocol"))
    implementation(project(":server"))
    implementation(project(":agents"))
    implementation(project(":viewer"))
    implementation(libs.slf4j.api)
    implementation(libs.logback.classic)
    implementation(libs.jsonschema.generator)
    implementation(libs.xchart)
    implementation(libs.picocli)

    testImplementation(platform(libs.junit.bom))
    testImplementation(libs.junit.jupiter)
    testImplementation(libs.assertj.core)
    testRuntimeOnly(libs.junit.platform.launcher)
}

application {
    // The orchard launcher: `gradle :examples:run --args="demo"`, or bin/orchard after installDist.
    mainClass = "io.orchard.examples.Orchard"
    applicationName = "orchard"
}

tasks.named<JavaExec>("run") {
    // The launcher's subcommands read commands from the console.
    standardInput = System.`in`
}

