/**
 * VRML97's classic encoding ({@code #VRML V2.0 utf8}): a tokenizer and a depth-bounded
 * recursive-descent parser into the format-neutral {@code SceneDescription}, and the
 * {@link io.orchard.viewer.model.vrml.FieldReader} that reads typed field values, which X3D's XML
 * encoding writes in the same syntax. PROTOs are skipped, EXTERNPROTOs never fetched.
 */
package io.orchard.viewer.model.vrml;
