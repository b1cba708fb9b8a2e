// How a published Orchard module (a library, or the BOM) is published, as the root pom.xml and
// bom/pom.xml describe it for Maven: a jar with an Automatic-Module-Name, its sources and its
// Javadoc, and a POM with the project's metadata. `gradle publishToMavenLocal` installs them;
// the repository and the signing are left to whoever releases (the Maven build's release profile).
// Applied by the published modules' build.gradle.kts, after their plugins block.
// BuildDriftTest reads this file: keep to the plain forms below.

val platform = plugins.hasPlugin("java-platform")

if (!platform) {
    configure<JavaPluginExtension> {
        withSourcesJar()
        withJavadocJar()
    }
    tasks.named<Jar>("jar") {
        manifest {
            attributes("Automatic-Module-Name" to "io.orchard.${project.name}")
        }
    }
    tasks.withType<Javadoc>().configureEach {
        // As the Maven build's javadoc plugin: doclint's checks but "missing", a warning fails.
        val doclet = options as StandardJavadocDocletOptions
        doclet.addStringOption("Xdoclint:all,-missing", "-quiet")
        doclet.addBooleanOption("Werror", true)
    }
}

configure<PublishingExtension> {
    publications {
        create<MavenPublication>("maven") {
            from(components[if (platform) "javaPlatform" else "java"])
            pom {
                name.set(if (platform) "Orchard BOM" else "Orchard ${project.name}")
                description.set(project.description)
                url.set("https://github.com/orchard-environment/orchard")
                inceptionYear.set("2026")
                licenses {
                    license {
                        name.set("Apache-2.0")
                        url.set("https://www.apache.org/licenses/LICENSE-2.0.txt")
                        distribution.set("repo")
                    }
                }
                developers {
                    developer {
                        id.set("orchard")
                        name.set("The Orchard developers")
                        url.set("https://github.com/orchard-environment/orchard")
                    }
                }
                scm {
                    connection.set("scm:git:https://github.com/orchard-environment/orchard.git")
                    developerConnection.set("scm:git:https://github.com/orchard-environment/orchard.git")
                    url.set("https://github.com/orchard-environment/orchard")
                    tag.set("HEAD")
                }
            }
        }
    }
}
