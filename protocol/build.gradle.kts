plugins {
    `java-library`
    `maven-publish`
}

apply(from = rootProject.file("gradle/java-conventions.gradle.kts"))
apply(from = rootProject.file("gradle/publish-conventions.gradle.kts"))

group = "io.orchard"
version = "0.1.0-SNAPSHOT"
description = "The typed messages of the Orchard protocol, their codec and a small blocking client connection. Depends on Jackson alone."

dependencies {
    // The messages are Jackson-serialisable records and the codec hands out Jackson types.
    api(libs.jackson.databind)

    testImplementation(libs.junit.jupiter)
    testImplementation(libs.assertj.core)
    testRuntimeOnly(libs.junit.platform.launcher)
}

