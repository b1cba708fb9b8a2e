import org.gradle.api.tasks.testing.logging.TestExceptionFormat

plugins {
    application
}

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

tasks.withType<JavaCompile>().configureEach {
    options.release = 17
    options.encoding = "UTF-8"
    options.compilerArgs.addAll(listOf("-Xlint:all,-processing,-serial", "-parameters"))
}

tasks.test {
    useJUnitPlatform()
    testLogging {
        events("failed")
        exceptionFormat = TestExceptionFormat.FULL
    }
}
