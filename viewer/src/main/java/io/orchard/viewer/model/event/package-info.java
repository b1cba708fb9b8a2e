/**
 * The VRML97/X3D event runtime, reduced to what agent models use: live nodes (TimeSensors,
 * Position-, Orientation- and ScalarInterpolators, Transforms, Materials) and the
 * {@link io.orchard.viewer.model.event.EventGraph} whose ROUTEs carry their events, stepped by
 * simulated time. The live Transforms and Materials keep the jME nodes and materials that show
 * them in step.
 */
package io.orchard.viewer.model.event;
