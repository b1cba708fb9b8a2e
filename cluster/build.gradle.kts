plugins {
    `java-library`
    `maven-publish`
}

apply(from = rootProject.file("gradle/java-conventions.gradle.kts"))
apply(from = rootProject.file("gradle/publish-conventions.gradle.kts"))

group = "io.orchard"
version = "0.1.0-SNAPSHOT"
description = "One world served by a cluster of servers: parcels of the world as Apache Pekko sharded entities, the tick as a cluster singleton."

dependencies {
    // The cluster runs the server's rules for each parcel of the world, and its front end on each node.
    api(project(":server"))
    implementation(project(":protocol"))
    implementation(project(":cli"))
    // NodeMain.command() hands its picocli CommandLine to launchers.
    api(libs.picocli)
    implementation(libs.pekko.cluster.sharding.typed)
    // The cluster's messages between nodes, as JSON: the Jackson the protocol brings.
    implementation(libs.jackson.databind)
    implementation(libs.slf4j.api)

    // The paper's agents, playing on one server and on a cluster in the tests.
    testImplementation(project(":agents"))
    testImplementation(libs.logback.classic)
    testImplementation(libs.junit.jupiter)
    testImplementation(libs.assertj.core)
    testRuntimeOnly(libs.junit.platform.launcher)
}

// Pekko's sharding brings LMDB (through distributed data) for durable storage of its state, which
// Orchard does not use, as the root pom.xml excludes it.
configurations.all {
    exclude(group = "org.lmdbjava", module = "lmdbjava")
}

// The heaviest tests run only with -PclusterFull, as Maven's cluster-full profile (docs/scaling.md).
tasks.withType<Test>().configureEach {
    if (!project.hasProperty("clusterFull")) {
        exclude("**/ClusterNodesTest*", "**/ShardedGameTest*")
    }
}
