// The Gradle build of Orchard. It is kept beside the Maven build (pom.xml), which stays the
// reference: the modules here, the versions in gradle/libs.versions.toml and each module's
// dependencies must match the poms, and examples' BuildDriftTest fails when they do not.

rootProject.name = "orchard"

dependencyResolutionManagement {
    repositoriesMode = RepositoriesMode.FAIL_ON_PROJECT_REPOS
    repositories {
        mavenCentral()
    }
}

include("protocol", "cli", "server", "agents", "viewer", "web", "cluster", "bom", "examples")
