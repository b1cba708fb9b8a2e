/**
 * The viewer's link to a live server, apart from the scene: a connection that says why it ended
 * (the server's closing error, the end of the stream, an I/O error) and connects again with a
 * growing wait while the server may come back ({@code ServerLink}, {@code Backoff}), and the keys
 * that start, pause and continue the game, which only the holder of the server's operator token may
 * use ({@code GameControls}). No jMonkeyEngine here: the app states use these, and tests drive them
 * against a real server.
 */
package io.orchard.viewer.live;
