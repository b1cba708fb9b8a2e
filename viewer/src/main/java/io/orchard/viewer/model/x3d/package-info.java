/**
 * X3D's XML encoding: the JDK's StAX parser with DTDs, external entities and external resources
 * off, read as a loop over events with an explicit stack into the format-neutral
 * {@code SceneDescription}. Attribute values are read by the VRML97 package's field reader.
 */
package io.orchard.viewer.model.x3d;
