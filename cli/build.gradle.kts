plugins {
    `java-library`
    `maven-publish`
}

apply(from = rootProject.file("gradle/java-conventions.gradle.kts"))
apply(from = rootProject.file("gradle/publish-conventions.gradle.kts"))

group = "io.orchard"
version = "0.1.0-SNAPSHOT"
description = "What the command lines of Orchard's programs share: picocli converters whose errors name the value and what was expected, and the handler that reports a wrong command line with exit status 2. Depends on picocli alone."

dependencies {
    // The converters and the handler are picocli types.
    api(libs.picocli)

    testImplementation(libs.junit.jupiter)
    testImplementation(libs.assertj.core)
    testRuntimeOnly(libs.junit.platform.launcher)
}
