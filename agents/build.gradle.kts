plugins {
    `java-library`
    `maven-publish`
}

apply(from = rootProject.file("gradle/java-conventions.gradle.kts"))
apply(from = rootProject.file("gradle/publish-conventions.gradle.kts"))

group = "io.orchard"
version = "0.1.0-SNAPSHOT"
description = "AgentController, the base every Orchard agent extends, its behaviours and the paper's five agents."

dependencies {
    api(project(":protocol"))
    implementation(project(":cli"))
    implementation(libs.slf4j.api)
    // AgentMain hands its picocli CommandLines to launchers.
    api(libs.picocli)
    // Checks a language model's goal against the goals' JSON Schema (LanguageModelInterpreter).
    implementation(libs.json.schema.validator) {
        // JSON schemas only; see agents/pom.xml for why YAML stays out.
        exclude(group = "tools.jackson.dataformat", module = "jackson-dataformat-yaml")
    }

    // Agents are tested against a real server, which they never depend on otherwise.
    testImplementation(project(":server"))
    testImplementation(libs.logback.classic)
    testImplementation(libs.jmh.core)
    testAnnotationProcessor(libs.jmh.generator.annprocess)
    testImplementation(libs.junit.jupiter)
    testImplementation(libs.assertj.core)
    testRuntimeOnly(libs.junit.platform.launcher)
}

// The JMH benchmark compiles with the tests so that it cannot rot (see docs/benchmarks.md).
sourceSets {
    test {
        java.srcDir("src/jmh/java")
    }
}
