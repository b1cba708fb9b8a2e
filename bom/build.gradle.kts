plugins {
    `java-platform`
    `maven-publish`
}

apply(from = rootProject.file("gradle/publish-conventions.gradle.kts"))

group = "io.orchard"
version = "0.1.0-SNAPSHOT"
description = "The versions of Orchard's published modules, which are released together: import it and depend on the modules without versions."

// Every published module, at this version, as bom/pom.xml manages them.
dependencies {
    constraints {
        api(project(":protocol"))
        api(project(":cli"))
        api(project(":server"))
        api(project(":agents"))
        api(project(":viewer"))
        api(project(":web"))
        api(project(":cluster"))
    }
}

// Published under the Maven build's artifactId, not the folder's name.
publishing {
    publications.named<MavenPublication>("maven") {
        artifactId = "orchard-bom"
    }
}
