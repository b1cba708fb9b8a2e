plugins {
    `java-library`
    `maven-publish`
}

apply(from = rootProject.file("gradle/java-conventions.gradle.kts"))
apply(from = rootProject.file("gradle/publish-conventions.gradle.kts"))

group = "io.orchard"
version = "0.1.0-SNAPSHOT"
description = "The browser viewer: a three.js page and the HTTP and WebSocket handlers that serve it and relay the protocol."

dependencies {
    // The web viewer provides the server's WebFrontEnd.
    api(project(":server"))
    implementation(project(":protocol"))
    implementation(libs.netty.codec.http)
    implementation(libs.netty.handler)
    implementation(libs.netty.codec.base)

    // Tested with the paper's agents against a real server, in Debian's Chromium.
    testImplementation(project(":agents"))
    testImplementation(libs.logback.classic)
    testImplementation(libs.junit.jupiter)
    testImplementation(libs.assertj.core)
    testRuntimeOnly(libs.junit.platform.launcher)
}

// The page and three.js, with Debian's node and npm as under Maven: `npm ci` installs three.js as
// package-lock.json pins it, and build.mjs copies the page and the parts of three.js it uses.
val npmCi by tasks.registering(Exec::class) {
    workingDir = projectDir
    commandLine("npm", "ci", "--no-audit", "--no-fund", "--prefer-offline")
    inputs.file("package-lock.json")
    outputs.dir("node_modules")
}

val page by tasks.registering(Exec::class) {
    dependsOn(npmCi)
    val site = layout.buildDirectory.dir("site/io/orchard/web/site")
    workingDir = projectDir
    inputs.dir("src/main/site")
    inputs.dir("../viewer/src/main/resources/io/orchard/viewer/bundled")
    inputs.file("build.mjs")
    outputs.dir(site)
    commandLine("node", "build.mjs", site.get().asFile.path)
}

sourceSets {
    main {
        resources.srcDir(files(layout.buildDirectory.dir("site")).builtBy(page))
    }
}
