// What every Orchard module compiles and tests with, as the root pom.xml sets it for Maven.
// Applied by each module's build.gradle.kts: apply(from = rootProject.file("gradle/java-conventions.gradle.kts"))
// BuildDriftTest reads this file: keep to the plain forms below.

// The BOMs the root pom.xml imports in its <dependencyManagement>, by their version catalog alias:
// each library family resolves to one version in every module, as under Maven.
val boms = listOf("jackson-bom", "netty-bom", "lwjgl-bom", "pekko-bom", "slf4j-bom", "junit-bom", "assertj-bom")

val catalog = extensions.getByType<VersionCatalogsExtension>().named("libs")
dependencies {
    for (bom in boms) {
        "implementation"(platform(catalog.findLibrary(bom).get()))
    }
}

tasks.withType<JavaCompile>().configureEach {
    options.release.set(17)
    options.encoding = "UTF-8"
    options.compilerArgs.addAll(listOf("-Xlint:all,-processing,-serial", "-parameters"))
}

tasks.withType<Test>().configureEach {
    useJUnitPlatform()
    // The heap Surefire and Failsafe give a test JVM (orchard.test.jvm in pom.xml), where Gradle's
    // own default would be 512 MiB.
    maxHeapSize = "2g"
    // ConsumerProjectIT installs and builds against Maven's packaged artifacts; it is Maven's alone.
    exclude("**/*IT.class", "**/*IT$*.class")
    testLogging {
        events("failed")
        exceptionFormat = org.gradle.api.tasks.testing.logging.TestExceptionFormat.FULL
    }
}
