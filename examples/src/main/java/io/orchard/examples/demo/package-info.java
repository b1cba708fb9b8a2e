/**
 * {@code ./orchard demo}: a whole match in one command — a world server embedded in this JVM, the
 * paper's five agents on threads of it, and the viewer: in a window where there is a display,
 * headless otherwise, writing a screenshot every ten seconds of the game.
 */
package io.orchard.examples.demo;
