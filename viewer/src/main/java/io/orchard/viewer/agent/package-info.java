/**
 * From an agent's {@code ModelSpec} to a model on screen: the viewer's bundled models (X3D files
 * named instead of sent, fitted to the agent's name and height), loading with the model package
 * and falling back to a labelled placeholder, with the reason, when a model cannot be shown.
 */
package io.orchard.viewer.agent;
