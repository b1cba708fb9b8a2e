package io.orchard.protocol.message;

import com.fasterxml.jackson.annotation.JsonValue;

/**
 * The stable codes of {@link ErrorMessage}. Clients may act on the code; the text is for people.
 */
public enum ErrorCode {
    /** The line is not one well-formed JSON object. */
    MALFORMED_JSON("malformed_json"),
    /** The {@code type} field is missing or names no message. */
    UNKNOWN_TYPE("unknown_type"),
    /** A required field is missing. */
    MISSING_FIELD("missing_field"),
    /** A field has the wrong JSON type, or a value out of range (NaN, infinity, negative size...). */
    INVALID_VALUE("invalid_value"),
    /** The message travels the other way: the server sends it, clients do not. */
    WRONG_DIRECTION("wrong_direction"),
    /** The line is longer than the protocol allows; the connection closes. */
    LINE_TOO_LONG("line_too_long"),
    /** The client speaks a protocol version the server does not; the connection closes. */
    VERSION_MISMATCH("version_mismatch"),
    /** A message other than Hello came before the handshake. */
    HANDSHAKE_REQUIRED("handshake_required"),
    /** The token in the hello is missing or wrong; the connection closes. */
    UNAUTHORIZED("unauthorized"),
    /** The message is not allowed in this client's role (a viewer registering an agent...). */
    WRONG_ROLE("wrong_role"),
    /**
     * The client may not do this (version 2): {@code GameControl} from a client that did not present
     * the operator token in its hello. A version 1 client gets {@link #WRONG_ROLE} instead.
     */
    FORBIDDEN("forbidden"),
    /** The named agent is not in the world. */
    UNKNOWN_AGENT("unknown_agent"),
    /** The named agent belongs to another connection. */
    NOT_YOUR_AGENT("not_your_agent"),
    /** Another agent already has the name. */
    NAME_IN_USE("name_in_use"),
    /** The connection has registered as many agents as it may. */
    TOO_MANY_AGENTS("too_many_agents"),
    /** The game is over or not running. */
    GAME_NOT_RUNNING("game_not_running"),
    /** The client sent more messages than the rate allows; the connection closes. */
    RATE_LIMITED("rate_limited"),
    /** The client did not read its messages fast enough; the connection closes. */
    SLOW_CONSUMER("slow_consumer"),
    /** The client sent nothing for too long; the connection closes. */
    IDLE("idle"),
    /** The server failed; the message had no effect; the connection closes. */
    INTERNAL_ERROR("internal_error");

    private final String wireName;

    ErrorCode(String wireName) {
        this.wireName = wireName;
    }

    /** The code on the wire. */
    @JsonValue
    public String wireName() {
        return wireName;
    }
}
