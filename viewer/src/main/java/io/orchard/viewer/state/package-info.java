/**
 * The viewer's app states, each a small part with its own lifecycle: where messages come from
 * ({@link io.orchard.viewer.state.LiveState} for a server, {@link io.orchard.viewer.state.ReplayState}
 * for a recording, each also the scene's clock), the static world and its fruit, the agents'
 * models, the camera, the selected agent's view cone, the panel of text, the instruction field,
 * replay keys, screenshots and frame-rate measures.
 *
 * <p>All of them run on the render thread, which alone owns the scene and the
 * {@link io.orchard.viewer.world.WorldMirror}; the connection's reader thread and the model loaders
 * hand their results to it with {@code Application.enqueue}.
 */
package io.orchard.viewer.state;
