/**
 * What a model file holds, read offline without a viewer: the names of its joints and clips (time
 * sensors), its bounding size and its units ({@link io.orchard.agents.model.ModelInfo}), so that an
 * agent's author knows what to register before connecting. {@code ./orchard model-info FILE} prints
 * it.
 */
package io.orchard.agents.model;
