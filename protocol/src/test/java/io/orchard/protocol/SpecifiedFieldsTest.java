package io.orchard.protocol;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import io.orchard.protocol.message.ErrorCode;
import io.orchard.protocol.message.GameStartedMessage;
import io.orchard.protocol.message.MoveMessage;
import io.orchard.protocol.message.RegisterMessage;
import io.orchard.protocol.message.WelcomeMessage;
import io.orchard.protocol.value.Bounds;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.GamePhase;
import io.orchard.protocol.value.ModelSpec;
import io.orchard.protocol.value.Role;
import io.orchard.protocol.value.Vec3;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** The fields whose rules docs/protocol.md states and the records follow: which are optional, and what they hold. */
class SpecifiedFieldsTest {

    private static final String BODY = "\"body\":{\"radius\":0.5,\"height\":1.2,\"maxSpeed\":8,\"gripper\":{\"part\":\"hands\","
            + "\"reach\":0.6,\"minHeight\":0,\"maxHeight\":1.5},\"sight\":{\"range\":30,\"fieldOfView\":3}}";

    private final MessageCodec codec = new MessageCodec();

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"figure", "bunny"})
    void aRegistrationNamingABundledModelThatExistsIsTaken(String name) {
        RegisterMessage register = (RegisterMessage) codec.decodeClient("{\"type\":\"Register\",\"seq\":2,\"name\":\"G\","
                + BODY + ",\"model\":{\"format\":\"bundled\",\"bundled\":\"" + name + "\"}}");
        assertThat(register.model()).isEqualTo(ModelSpec.bundled(name));
    }

    @Test
    void aRegistrationNamingABundledModelThatDoesNotExistIsRefusedNamingTheOnesThatDo() {
        String line = "{\"type\":\"Register\",\"seq\":4,\"name\":\"G\"," + BODY
                + ",\"model\":{\"format\":\"bundled\",\"bundled\":\"no_such_model\"}}";
        assertThatThrownBy(() -> codec.decodeClient(line))
                .isInstanceOf(ProtocolException.class)
                .hasMessage("model.bundled must be one of 'figure', 'bunny', was 'no_such_model'")
                .satisfies(e -> assertThat(((ProtocolException) e).code()).isEqualTo(ErrorCode.INVALID_VALUE))
                .satisfies(e -> assertThat(((ProtocolException) e).seq()).isEqualTo(4));
    }

    @Test
    void aViewerReadsAnAgentWithABundledModelItDoesNotKnowToShowAPlaceholder() {
        String added = "{\"type\":\"AgentAdded\",\"tick\":3,\"agent\":{\"name\":\"G\"," + BODY + ",\"position\":"
                + "{\"x\":0,\"y\":0,\"z\":0},\"heading\":0,\"model\":{\"format\":\"bundled\",\"bundled\":\"dragon\"},"
                + "\"joints\":[],\"timeSensors\":[]}}";
        assertThat(codec.decodeServer(added)).isNotNull();
    }

    @Test
    void aBundledModelWithoutItsNameIsAMissingField() {
        assertThatThrownBy(() -> codec.decodeClient("{\"type\":\"Register\",\"seq\":2,\"name\":\"G\"," + BODY
                + ",\"model\":{\"format\":\"bundled\"}}"))
                .hasMessage("missing field 'model.bundled'")
                .satisfies(e -> assertThat(((ProtocolException) e).code()).isEqualTo(ErrorCode.MISSING_FIELD));
    }

    @Test
    void aNullModelIsAnAbsentOne() {
        RegisterMessage register = (RegisterMessage) codec.decodeClient("{\"type\":\"Register\",\"seq\":2,\"name\":\"G\","
                + BODY + ",\"model\":null}");
        assertThat(register.model()).isNull();
    }

    @ParameterizedTest(name = "from [{0}]")
    @ValueSource(strings = {"", ",\"from\":null"})
    void aMoveMayLeaveOutFrom(String from) {
        MoveMessage move = (MoveMessage) codec.decodeClient("{\"type\":\"Move\",\"seq\":6,\"agent\":\"Guppy\"" + from
                + ",\"to\":{\"x\":1,\"y\":0,\"z\":2}}");
        assertThat(move.from()).isNull();
        assertThat(move).isEqualTo(new MoveMessage(6, "Guppy", new Vec3(1, 0, 2)));
        assertThat(codec.encode(move)).isEqualTo("{\"type\":\"Move\",\"seq\":6,\"agent\":\"Guppy\","
                + "\"to\":{\"x\":1.0,\"y\":0.0,\"z\":2.0}}");
    }

    @Test
    void aMoveStillNeedsTo() {
        assertThatThrownBy(() -> codec.decodeClient("{\"type\":\"Move\",\"seq\":6,\"agent\":\"Guppy\"}"))
                .hasMessage("missing field 'to'");
    }

    @Test
    void theWelcomeOfVersion2CarriesTheTimeLimitAndThePhaseAndThatOfVersion1DoesNot() {
        WelcomeMessage welcome = new WelcomeMessage(1, 2, "0.1.0", Role.AGENT, new Bounds(-1, -1, 1, 1), 20,
                ClockMode.REALTIME, 40, 300.0, GamePhase.RUNNING);
        assertThat(codec.encode(welcome)).endsWith(",\"tick\":40,\"timeLimit\":300.0,\"phase\":\"running\"}");
        assertThat(welcome.forVersion(2)).isSameAs(welcome);
        WelcomeMessage first = welcome.forVersion(1);
        assertThat(first.timeLimit()).isNull();
        assertThat(first.phase()).isNull();
        assertThat(codec.encode(first)).endsWith(",\"tick\":40}");
        assertThat(codec.decode(codec.encode(welcome))).isEqualTo(welcome);
    }

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"waiting", "running", "paused", "over"})
    void everyPhaseIsReadByItsWireName(String phase) {
        WelcomeMessage welcome = (WelcomeMessage) codec.decodeServer("{\"type\":\"Welcome\",\"seq\":1,"
                + "\"protocolVersion\":2,\"serverVersion\":\"x\",\"role\":\"viewer\",\"bounds\":{\"minX\":-1,\"minZ\":-1,"
                + "\"maxX\":1,\"maxZ\":1},\"tickRate\":20,\"clock\":\"lockstep\",\"tick\":0,\"phase\":\"" + phase + "\"}");
        assertThat(welcome.phase().wireName()).isEqualTo(phase);
    }

    @Test
    void aNegativeTimeLimitInTheWelcomeIsRefused() {
        assertThatThrownBy(() -> new WelcomeMessage(1, 2, "x", Role.AGENT, new Bounds(-1, -1, 1, 1), 20,
                ClockMode.REALTIME, 0, -1.0, null))
                .hasMessage("timeLimit must not be negative, was -1.0");
    }

    @Test
    void theGameStartedOfAnAgentClientHasNoSeed() {
        GameStartedMessage started = new GameStartedMessage(0, 1998, 30, 180);
        assertThat(started.seed()).isEqualTo(1998L);
        GameStartedMessage blind = started.withoutSeed();
        assertThat(blind.seed()).isNull();
        assertThat(codec.encode(blind)).isEqualTo("{\"type\":\"GameStarted\",\"tick\":0,\"fruitCount\":30,\"timeLimit\":180.0}");
        assertThat(codec.decode(codec.encode(blind))).isEqualTo(blind);
    }
}
