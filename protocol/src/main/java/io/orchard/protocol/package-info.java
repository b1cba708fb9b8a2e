/**
 * The Orchard protocol: its {@linkplain io.orchard.protocol.MessageCodec codec} (newline-delimited
 * JSON), its {@linkplain io.orchard.protocol.ProtocolVersion version} and the
 * {@linkplain io.orchard.protocol.ProtocolException error} a bad line raises, and
 * {@linkplain io.orchard.protocol.StrictJson the one Jackson configuration} that the codec, scenario
 * and checkpoint files and the viewer's glTF guard are built on. The messages live in
 * {@code io.orchard.protocol.message}, the values they carry in {@code io.orchard.protocol.value},
 * and a small blocking connection on the JDK alone in {@code io.orchard.protocol.client}.
 */
package io.orchard.protocol;
