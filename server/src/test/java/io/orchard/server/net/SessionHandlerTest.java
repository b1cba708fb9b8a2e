package io.orchard.server.net;

import static org.assertj.core.api.Assertions.assertThat;

import io.netty.channel.embedded.EmbeddedChannel;
import io.netty.handler.timeout.IdleStateEvent;
import io.orchard.protocol.message.ClientMessage;
import io.orchard.protocol.message.EndTurnMessage;
import io.orchard.protocol.ProtocolVersion;
import io.orchard.protocol.message.ErrorCode;
import io.orchard.protocol.message.ErrorMessage;
import io.orchard.protocol.message.GameControlMessage;
import io.orchard.protocol.message.HelloMessage;
import io.orchard.protocol.message.WelcomeMessage;
import io.orchard.protocol.value.Bounds;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.GameCommand;
import io.orchard.protocol.value.Role;
import io.orchard.server.sim.ClientSession;
import io.orchard.server.sim.Inbox;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.provider.ValueSource;
import org.junit.jupiter.params.ParameterizedTest;

/** The handshake and what follows it, on an embedded channel with an inbox that only listens. */
class SessionHandlerTest {

    /** An inbox that keeps what the session hands it. */
    static final class ListeningInbox implements Inbox {
        final List<ClientSession> connected = new ArrayList<>();
        final List<ClientMessage> received = new ArrayList<>();
        final List<String> disconnected = new ArrayList<>();

        @Override
        public void connected(ClientSession session) {
            connected.add(session);
        }

        @Override
        public void received(ClientSession session, ClientMessage message) {
            received.add(message);
        }

        @Override
        public void disconnected(ClientSession session, String reason) {
            disconnected.add(reason);
        }

        @Override
        public WelcomeMessage welcome(long seq, Role role, int protocolVersion) {
            return new WelcomeMessage(seq, protocolVersion, "test", role, new Bounds(-1, -1, 1, 1), 20, ClockMode.REALTIME, 0);
        }
    }

    private final ListeningInbox inbox = new ListeningInbox();

    private EmbeddedChannel channel(String token) {
        return new EmbeddedChannel(new SessionHandler(SessionContext.of(inbox, token, NetLimits.DEFAULT)));
    }

    private EmbeddedChannel operatedChannel(String operatorToken) {
        return new EmbeddedChannel(new SessionHandler(SessionContext.of(inbox, null, operatorToken, NetLimits.DEFAULT)));
    }

    private static HelloMessage hello(int version, String token) {
        return new HelloMessage(1, version, Role.AGENT, "test", token);
    }

    @Test
    void aHelloIsWelcomedAndTheSessionHandedToTheSimulation() {
        EmbeddedChannel channel = channel(null);
        channel.writeInbound(hello(1, null));
        WelcomeMessage welcome = channel.readOutbound();
        assertThat(welcome.seq()).isEqualTo(1);
        assertThat(welcome.role()).isEqualTo(Role.AGENT);
        assertThat(inbox.connected).singleElement().satisfies(s -> assertThat(s.role()).isEqualTo(Role.AGENT));
        channel.writeInbound(new EndTurnMessage(2, 0));
        assertThat(inbox.received).containsExactly(new EndTurnMessage(2, 0));
        channel.close();
        assertThat(inbox.disconnected).containsExactly("connection closed");
    }

    @Test
    void messagesBeforeTheHelloAreRefusedAndTheConnectionStaysOpen() {
        EmbeddedChannel channel = channel(null);
        channel.writeInbound(new EndTurnMessage(7, 0));
        ErrorMessage error = channel.readOutbound();
        assertThat(error.code()).isEqualTo(ErrorCode.HANDSHAKE_REQUIRED);
        assertThat(error.seq()).isEqualTo(7);
        assertThat(error.text()).contains("was EndTurn");
        assertThat(inbox.received).isEmpty();
        assertThat(channel.isOpen()).isTrue();
    }

    @Test
    void aSecondHelloIsRefused() {
        EmbeddedChannel channel = channel(null);
        channel.writeInbound(hello(1, null));
        channel.readOutbound();
        channel.writeInbound(hello(1, null));
        assertThat(((ErrorMessage) channel.readOutbound()).code()).isEqualTo(ErrorCode.INVALID_VALUE);
        assertThat(inbox.connected).hasSize(1);
    }

    @Test
    void anotherProtocolVersionIsRefusedAndClosed() {
        EmbeddedChannel channel = channel(null);
        channel.writeInbound(hello(ProtocolVersion.CURRENT + 1, null));
        ErrorMessage error = channel.readOutbound();
        assertThat(error.code()).isEqualTo(ErrorCode.VERSION_MISMATCH);
        assertThat(error.text()).contains("client asked for " + (ProtocolVersion.CURRENT + 1));
        assertThat(channel.isOpen()).isFalse();
        assertThat(inbox.connected).isEmpty();
    }

    @ParameterizedTest
    @ValueSource(ints = {1, 2})
    void everyVersionFromTheOldestToTheCurrentIsWelcomed(int version) {
        EmbeddedChannel channel = channel(null);
        channel.writeInbound(hello(version, null));
        assertThat((Object) channel.readOutbound()).isInstanceOf(WelcomeMessage.class);
        assertThat(channel.isOpen()).isTrue();
        assertThat(inbox.connected).hasSize(1);
    }

    @ParameterizedTest
    @ValueSource(ints = {1, 2})
    void theWelcomeAndTheSessionSpeakTheVersionOfTheHello(int version) {
        EmbeddedChannel channel = channel(null);
        channel.writeInbound(hello(version, null));
        assertThat(((WelcomeMessage) channel.readOutbound()).protocolVersion()).isEqualTo(version);
        assertThat(inbox.connected).singleElement().satisfies(s -> assertThat(s.protocolVersion()).isEqualTo(version));
    }

    @Test
    void anIdleConnectionIsToldWhyAndClosed() {
        EmbeddedChannel channel = channel(null);
        channel.pipeline().fireUserEventTriggered(IdleStateEvent.FIRST_READER_IDLE_STATE_EVENT);
        assertThat(((ErrorMessage) channel.readOutbound()).code()).isEqualTo(ErrorCode.IDLE);
        assertThat(channel.isOpen()).isFalse();
    }

    @Test
    void aWelcomedViewerLeavesTheIdleTimeoutBehindAndAnAgentKeepsIt() {
        for (Role role : Role.values()) {
            EmbeddedChannel channel = new EmbeddedChannel(
                    new HelloDeadline(new HelloQueue(8), java.time.Duration.ofSeconds(5)),
                    new io.netty.handler.timeout.IdleStateHandler(120, 0, 0),
                    new SessionHandler(SessionContext.of(inbox, null, NetLimits.DEFAULT)));
            channel.writeInbound(new HelloMessage(1, 1, role, "test", null));
            assertThat(channel.pipeline().get(HelloDeadline.class)).as("the Hello came").isNull();
            assertThat(channel.pipeline().get(io.netty.handler.timeout.IdleStateHandler.class) != null)
                    .as("idle timeout for a " + role.wireName()).isEqualTo(role == Role.AGENT);
            channel.close();
        }
    }

    @Nested
    class GameControl {

        private final GameControlMessage pause = new GameControlMessage(5, GameCommand.PAUSE);

        private HelloMessage operatorHello(int version, String operatorToken) {
            return new HelloMessage(1, version, Role.VIEWER, "test", null, operatorToken);
        }

        @Test
        void theOperatorsIsHandedToTheSimulation() {
            EmbeddedChannel channel = operatedChannel("op-s3cret");
            channel.writeInbound(operatorHello(2, "op-s3cret"));
            assertThat((Object) channel.readOutbound()).isInstanceOf(WelcomeMessage.class);
            channel.writeInbound(pause);
            assertThat(inbox.received).containsExactly(pause);
            assertThat((Object) channel.readOutbound()).isNull();
        }

        @Test
        void anyoneElsesIsForbiddenAndTheConnectionStaysOpen() {
            EmbeddedChannel channel = operatedChannel("op-s3cret");
            channel.writeInbound(operatorHello(2, null));
            channel.readOutbound();
            channel.writeInbound(pause);
            ErrorMessage error = channel.readOutbound();
            assertThat(error.code()).isEqualTo(ErrorCode.FORBIDDEN);
            assertThat(error.seq()).isEqualTo(5);
            assertThat(error.text()).isEqualTo("GameControl pause is the operator's: it needs the server's operator"
                    + " token in Hello (operatorToken)");
            assertThat(inbox.received).isEmpty();
            assertThat(channel.isOpen()).isTrue();
        }

        @Test
        void withoutAnOperatorTokenNoClientControlsTheGame() {
            EmbeddedChannel channel = operatedChannel(null);
            channel.writeInbound(operatorHello(2, null));
            channel.readOutbound();
            channel.writeInbound(pause);
            ErrorMessage error = channel.readOutbound();
            assertThat(error.code()).isEqualTo(ErrorCode.FORBIDDEN);
            assertThat(error.text()).contains("this server has no operator token, so only its console and the"
                    + " program that embeds it control the game");
            assertThat(inbox.received).isEmpty();
        }

        @Test
        void aWrongOperatorTokenIsRefusedAndClosedWithoutSayingWhatIsRight() {
            EmbeddedChannel channel = operatedChannel("op-s3cret");
            channel.writeInbound(operatorHello(2, "op-s3cres"));
            ErrorMessage error = channel.readOutbound();
            assertThat(error.code()).isEqualTo(ErrorCode.UNAUTHORIZED);
            assertThat(error.text()).isEqualTo("wrong operator token");
            assertThat(channel.isOpen()).isFalse();
            assertThat(inbox.connected).isEmpty();
        }

        @Test
        void anOperatorTokenForAServerWithoutOneIsRefusedAndClosed() {
            EmbeddedChannel channel = operatedChannel(null);
            channel.writeInbound(operatorHello(2, "op-s3cret"));
            ErrorMessage error = channel.readOutbound();
            assertThat(error.code()).isEqualTo(ErrorCode.UNAUTHORIZED);
            assertThat(error.text()).contains("this server has no operator token");
            assertThat(channel.isOpen()).isFalse();
        }

        @Test
        void aVersion1ClientHasNoOperatorTokenAndIsToldWrongRoleWhichItKnows() {
            EmbeddedChannel channel = operatedChannel("op-s3cret");
            channel.writeInbound(operatorHello(1, "op-s3cret"));
            assertThat(((WelcomeMessage) channel.readOutbound()).protocolVersion()).isEqualTo(1);
            channel.writeInbound(pause);
            ErrorMessage error = channel.readOutbound();
            assertThat(error.code()).isEqualTo(ErrorCode.WRONG_ROLE);
            assertThat(error.text()).contains("protocol version 1");
            assertThat(inbox.received).isEmpty();
        }
    }

    @Nested
    class WithAToken {

        @Test
        void theRightTokenIsWelcomed() {
            EmbeddedChannel channel = channel("s3cret");
            channel.writeInbound(hello(1, "s3cret"));
            assertThat((Object) channel.readOutbound()).isInstanceOf(WelcomeMessage.class);
        }

        @Test
        void aMissingTokenIsRefusedAndClosed() {
            EmbeddedChannel channel = channel("s3cret");
            channel.writeInbound(hello(1, null));
            ErrorMessage error = channel.readOutbound();
            assertThat(error.code()).isEqualTo(ErrorCode.UNAUTHORIZED);
            assertThat(error.text()).contains("requires a token");
            assertThat(channel.isOpen()).isFalse();
        }

        @Test
        void aWrongTokenIsRefusedAndClosedWithoutSayingWhatIsRight() {
            EmbeddedChannel channel = channel("s3cret");
            channel.writeInbound(hello(1, "s3cres"));
            ErrorMessage error = channel.readOutbound();
            assertThat(error.code()).isEqualTo(ErrorCode.UNAUTHORIZED);
            assertThat(error.text()).isEqualTo("wrong token");
            assertThat(channel.isOpen()).isFalse();
            assertThat(inbox.connected).isEmpty();
        }
    }
}
