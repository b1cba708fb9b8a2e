/**
 * From a scene description to jMonkeyEngine: the {@link io.orchard.viewer.model.build.SceneBuilder}
 * makes spatials, meshes (primitives, face and line sets) and materials, and the live nodes of
 * the event graph; {@link io.orchard.viewer.model.build.Placeholders} make the stand-in for a model
 * that cannot be shown. The rigs then move, pose and animate what was built: through the event
 * graph for VRML97 and X3D ({@link io.orchard.viewer.model.build.EventGraphRig}), on the spatials
 * directly for glTF and placeholders ({@link io.orchard.viewer.model.build.SpatialRig}).
 */
package io.orchard.viewer.model.build;
