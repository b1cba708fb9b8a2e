/**
 * Builders of the world's look: ground, river and bridges, the castle with its walls and towers,
 * trees, tables and the three kinds of fruit, the sky, and the meshes they are made of. Each
 * builder turns protocol values into jME spatials and touches no live scene, so the app states
 * decide when to attach what they build.
 *
 * <p>Sizes follow the protocol's 2.5D model: a tree is drawn from its bounding cylinder (trunk as
 * the server's blocking radius, crown filling the cylinder's top), a table from its cylinder, the
 * castle by extruding its footprint, fruit at its radius and height.
 */
package io.orchard.viewer.scene;
