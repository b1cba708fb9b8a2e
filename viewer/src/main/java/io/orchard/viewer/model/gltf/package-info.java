/**
 * glTF 2.0 and GLB, loaded by jMonkeyEngine's own loaders from the bytes in memory after a guard
 * has read the JSON and refused what those loaders would handle dangerously: external URIs,
 * nesting or sizes over the limits, node cycles, accessors and images too large.
 */
package io.orchard.viewer.model.gltf;
