// What every Orchard module compiles and tests with, as the root pom.xml sets it for Maven.
// Applied by each module's build.gradle.kts: apply(from = rootProject.file("gradle/java-conventions.gradle.kts"))

tasks.withType<JavaCompile>().configureEach {
    options.release.set(17)
    options.encoding = "UTF-8"
    options.compilerArgs.addAll(listOf("-Xlint:all,-processing,-serial", "-parameters"))
}

tasks.withType<Test>().configureEach {
    useJUnitPlatform()
    testLogging {
        events("failed")
        exceptionFormat = org.gradle.api.tasks.testing.logging.TestExceptionFormat.FULL
    }
}
