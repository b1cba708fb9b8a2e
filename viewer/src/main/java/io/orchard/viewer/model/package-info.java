/**
 * Agent models: loading the bodies agents register with, and moving, posing and animating them.
 * This package and the ones below it take the place of the paper's VRML browser and its External
 * Authoring Interface.
 *
 * <p>The rest of the viewer uses five types: {@link io.orchard.viewer.model.BodyModels} loads a
 * model from bytes in one of the protocol's {@code ModelFormat}s (glTF, GLB, X3D or VRML97)
 * within {@link io.orchard.viewer.model.ModelLimits}, giving a
 * {@link io.orchard.viewer.model.BodyModel} or a {@link io.orchard.viewer.model.ModelException};
 * {@link io.orchard.viewer.model.ModelFormats} tells a file's format from its name or first bytes.
 * The viewer maps protocol messages onto the body model's methods and calls {@code update} with
 * the simulated time each frame.
 *
 * <p>The other public types here are what the packages below share, not meant for the rest of
 * the viewer: the format-neutral scene description both VRML97 and X3D parse into
 * ({@link io.orchard.viewer.model.SceneDescription} of {@link io.orchard.viewer.model.SceneNode}s,
 * typed by the {@link io.orchard.viewer.model.NodeSchema}, with DEF/USE resolved and ROUTEs
 * checked), the {@link io.orchard.viewer.model.ParseBudget} every parser counts against the
 * limits, embedded images, rotations, and the {@link io.orchard.viewer.model.Rig} a body model
 * drives. Below: {@code vrml}, {@code x3d} and {@code gltf}, one package per format; {@code event},
 * the VRML97/X3D event runtime (TimeSensors, interpolators, ROUTEs); {@code build}, which turns a
 * scene description into jME spatials and holds the rigs.
 *
 * <p>Models are untrusted input: nothing is ever fetched or read beyond the given bytes, limits
 * are enforced while parsing, and failures are reported only as {@code ModelException}.
 */
package io.orchard.viewer.model;
