/**
 * Agent models: loading the bodies agents register with, and moving, posing and animating them.
 * This package takes the place of the paper's VRML browser and its External Authoring Interface.
 *
 * <p>The public surface is small: {@link io.orchard.viewer.model.AgentModels} loads a model from
 * bytes in a {@link io.orchard.viewer.model.ModelFormat} (glTF, GLB, X3D or VRML97) within
 * {@link io.orchard.viewer.model.ModelLimits}, giving an {@link io.orchard.viewer.model.AgentModel}
 * or a {@link io.orchard.viewer.model.ModelException}; the viewer maps protocol messages onto the
 * model's methods and calls {@code update} with the simulated time each frame.
 *
 * <p>Inside, VRML97 (a tokenizer and a depth-bounded recursive-descent parser) and X3D (the JDK's
 * StAX parser with DTDs and external entities off) produce the same format-neutral scene
 * description, with DEF/USE resolved and ROUTEs checked. A builder turns it into jME spatials,
 * named after their DEF names, and an event graph of live nodes (TimeSensors, interpolators,
 * Transforms, Materials) that ROUTEs connect. glTF goes through jME's own loader, after a guard
 * has refused external URIs and oversized or cyclic documents.
 *
 * <p>Models are untrusted input: nothing is ever fetched or read beyond the given bytes, limits
 * are enforced while parsing, and failures are reported only as {@code ModelException}.
 */
package io.orchard.viewer.model;
