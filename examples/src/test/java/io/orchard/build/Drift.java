package io.orchard.build;

/**
 * One way in which the Gradle build no longer says what the Maven build says.
 *
 * @param item   what drifted, e.g. {@code "version jts"} or {@code "server dependency io.netty:netty-handler"}
 * @param maven  what the Maven build has (the version Maven resolves, for resolved versions)
 * @param gradle what the Gradle build has
 */
record Drift(String item, String maven, String gradle) {

    /** The word used for a side that lacks the item altogether. */
    static final String ABSENT = "absent";

    @Override
    public String toString() {
        return item + " [Maven: " + maven + ", Gradle: " + gradle + "]";
    }
}
