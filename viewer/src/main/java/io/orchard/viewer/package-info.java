/**
 * The Orchard viewer: the paper's VRML browser and applet client in one jMonkeyEngine
 * application. {@link io.orchard.viewer.ViewerMain} is its command line: it watches a live server
 * as a viewer client, or replays a recording the server wrote; in a window, or headless under an
 * X display such as Xvfb, writing screenshots at given simulated times and exiting.
 *
 * <p>The application only assembles small app states (package {@code state}); the world it shows
 * is kept without graphics in package {@code world}, drawn by the builders of package
 * {@code scene}, and agents' bodies come through package {@code agent} from the model loaders of
 * package {@code model}. One thread, the render thread, owns the scene and the world model; the
 * connection and the model loaders hand it their results with {@code enqueue}.
 */
package io.orchard.viewer;
