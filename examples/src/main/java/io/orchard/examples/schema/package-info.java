/**
 * The protocol's JSON Schema, generated from the message records: {@link
 * io.orchard.examples.schema.ProtocolSchema} builds it and {@link
 * io.orchard.examples.schema.ProtocolSchemaCommand} is {@code ./orchard protocol-schema}.
 */
package io.orchard.examples.schema;
