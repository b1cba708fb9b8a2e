plugins {
    application
}

apply(from = rootProject.file("gradle/java-conventions.gradle.kts"))

group = "io.orchard"
version = "0.1.0-SNAPSHOT"
description = "Runnable programs: the orchard launcher, the demo, embedding, a first agent and tournaments."

dependencies {
    implementation(project(":protocol"))
    implementation(project(":cli"))
    implementation(project(":server"))
    implementation(project(":agents"))
    implementation(project(":viewer"))
    implementation(project(":cluster"))
    // The server's browser viewer, found on the class path when a page is asked for.
    runtimeOnly(project(":web"))
    implementation(libs.slf4j.api)
    implementation(libs.logback.classic)
    implementation(libs.jsonschema.generator)
    implementation(libs.xchart)
    implementation(libs.picocli)

    testImplementation(libs.junit.jupiter)
    testImplementation(libs.assertj.core)
    testImplementation(libs.archunit.junit5)
    testImplementation(libs.json.schema.validator)
    testRuntimeOnly(libs.junit.platform.launcher)
}

application {
    // The orchard launcher: `gradle :examples:run --args="demo"`, or bin/orchard after installDist.
    mainClass = "io.orchard.examples.Orchard"
    applicationName = "orchard"
}

tasks.named<JavaExec>("run") {
    // In the directory gradle was started from, as ./orchard runs, so that relative paths in the
    // arguments (--out, --resume, --replay) mean what they say, not a path inside examples/.
    workingDir = gradle.startParameter.currentDir
    // The launcher's subcommands read commands from the console.
    standardInput = System.`in`
}

