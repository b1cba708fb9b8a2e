package io.orchard.protocol.message;

import com.fasterxml.jackson.annotation.JsonTypeInfo;

/**
 * A message of the Orchard protocol: one JSON object on one line, whose {@code type} field is the
 * record's name without the {@code Message} suffix ({@code MoveMessage} travels as
 * {@code "type":"Move"}). Messages are immutable records that validate themselves on construction.
 *
 * <p>Messages are grouped by direction: {@link ClientMessage} from clients to the server,
 * {@link ServerMessage} from the server to clients. {@link InstructionMessage} and
 * {@link SayMessage} travel both ways. The interfaces and the records share this package because a
 * sealed hierarchy outside a named module must stay within one package.
 */
@JsonTypeInfo(use = JsonTypeInfo.Id.NAME, include = JsonTypeInfo.As.PROPERTY, property = "type")
public sealed interface Message permits ClientMessage, ServerMessage {
}
