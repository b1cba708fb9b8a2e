package io.orchard.protocol;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import io.orchard.protocol.message.CastlePerceptionMessage;
import io.orchard.protocol.message.HelloMessage;
import io.orchard.protocol.message.LandmarkPerceptionMessage;
import io.orchard.protocol.message.LeanPerceptionMessage;
import io.orchard.protocol.message.PerceptionMessage;
import io.orchard.protocol.value.Form;
import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.LeanUnits;
import io.orchard.protocol.value.ObjectKind;
import io.orchard.protocol.value.PerceivedAgent;
import io.orchard.protocol.value.PerceivedBridge;
import io.orchard.protocol.value.PerceivedFruit;
import io.orchard.protocol.value.PerceivedObject;
import io.orchard.protocol.value.PerceivedRiver;
import io.orchard.protocol.value.RelativePosition;
import io.orchard.protocol.value.Role;
import io.orchard.protocol.value.Sector;
import io.orchard.protocol.value.Vec3;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** The lean perception carries what the three perception messages carry, at the precision the server promises. */
class LeanPerceptionTest {

    private final MessageCodec codec = new MessageCodec();
    private final Random random = new Random(1998);

    @Test
    void theSampleComesBackExactlyFromItsLine() {
        LeanPerceptionMessage lean = LeanPerceptionMessage.of(Samples.PERCEPTION, Samples.LANDMARKS, Samples.CASTLE);
        LeanPerceptionMessage decoded = (LeanPerceptionMessage) codec.decodeServer(codec.encode(lean));
        assertThat(decoded.toPerception()).isEqualTo(Samples.PERCEPTION);
        assertThat(decoded.toLandmarks()).isEqualTo(Samples.LANDMARKS);
        assertThat(decoded.toCastle()).isEqualTo(Samples.CASTLE);
    }

    @Test
    void oneLineIsMuchShorterThanTheThree() {
        int three = codec.encodeLine(Samples.PERCEPTION).length + codec.encodeLine(Samples.LANDMARKS).length
                + codec.encodeLine(Samples.CASTLE).length;
        int lean = codec.encodeLine(LeanPerceptionMessage.of(Samples.PERCEPTION, Samples.LANDMARKS, Samples.CASTLE))
                .length;
        assertThat(lean).isLessThan(three / 2);
    }

    /**
     * Perceptions as the server rounds them (positions and distances to 0.01, angles to 0.001, π
     * included) with sizes as a scenario may give them: rebuilt from the lean line, everything is
     * equal, sizes to the centimetre.
     */
    @Test
    void perceptionsAsTheServerRoundsThemComeBackEqualAtThatPrecision() {
        for (int n = 0; n < 500; n++) {
            PerceptionMessage seen = perception(n);
            LandmarkPerceptionMessage landmarks = landmarks(n);
            CastlePerceptionMessage castle = new CastlePerceptionMessage(n, "Guppy",
                    Sector.values()[random.nextInt(8)]);
            LeanPerceptionMessage lean = (LeanPerceptionMessage) codec.decodeServer(
                    codec.encode(LeanPerceptionMessage.of(seen, landmarks, castle)));
            assertThat(lean.toPerception()).isEqualTo(sizesInCentimetres(seen));
            assertThat(lean.toLandmarks()).isEqualTo(sizesInCentimetres(landmarks));
            assertThat(lean.toCastle()).isEqualTo(castle);
        }
    }

    @Test
    void aBearingOfPiStaysPi() {
        assertThat(LeanUnits.milliradians(Math.PI)).isEqualTo(LeanUnits.PI_MILLIRADIANS);
        assertThat(LeanUnits.radians(LeanUnits.PI_MILLIRADIANS)).isEqualTo(Math.PI);
        assertThat(LeanUnits.radians(-3141)).isEqualTo(-3.141);
    }

    @Test
    void aSizeIsAtLeastOneCentimetre() {
        assertThat(LeanUnits.size(0.004)).isEqualTo(1);
        assertThat(LeanUnits.size(0.015)).isEqualTo(2);
    }

    @Test
    void partsOfDifferentTicksOrAgentsAreNotOnePerception() {
        assertThatThrownBy(() -> LeanPerceptionMessage.of(Samples.PERCEPTION, Samples.LANDMARKS,
                new CastlePerceptionMessage(44, "Guppy", Sector.NORTH)))
                .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("Guppy at 44");
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', textBlock = """
        a tuple one short          | [["T17","tree",650,-400,150]]       | []                 | missing_field | missing field 'objects[0].height'
        a bearing beyond pi        | [["T17","tree",650,-3142,150,600]]  | []                 | invalid_value | objects[0].bearing must be a bearing in milliradians from -3141 to 3142, was -3142
        a fraction for centimetres | [["T17","tree",650.5,-400,150,600]] | []                 | invalid_value | 'objects[0]'
        an object for a tuple      | [{"id":"T17"}]                      | []                 | invalid_value | 'objects[0]'
        a size of nothing          | [["T17","tree",650,-400,150,0]]     | []                 | invalid_value | objects[0].height must be at least 1 (centimetre), was 0
        a negative distance        | []                                  | [["Bunny",-1,0,0,40]] | invalid_value | agents[0].distance must not be negative, was -1
        """)
    void badTuplesAreRefusedNamingTheElement(String name, String objects, String agents, String code, String fragment) {
        String line = "{\"type\":\"LeanPerception\",\"tick\":43,\"agent\":\"Guppy\",\"position\":[1250,0,-4025],"
                + "\"heading\":250,\"objects\":" + objects + ",\"agents\":" + agents + ",\"fruit\":[],\"bridges\":[],"
                + "\"castle\":\"north\"}";
        assertThatThrownBy(() -> codec.decodeServer(line))
                .isInstanceOf(ProtocolException.class)
                .hasMessageContaining(fragment)
                .extracting(e -> ((ProtocolException) e).code().wireName()).isEqualTo(code);
    }

    @Test
    void elementsBeyondATuplesAreIgnoredAsUnknownFieldsAre() {
        LeanPerceptionMessage lean = (LeanPerceptionMessage) codec.decodeServer("{\"type\":\"LeanPerception\","
                + "\"tick\":1,\"agent\":\"Guppy\",\"position\":[0,0,0],\"heading\":0,\"objects\":[],\"agents\":[],"
                + "\"fruit\":[[\"F1\",\"coconut\",100,35,-200,null,\"later\"]],\"bridges\":[],\"castle\":\"east\"}");
        assertThat(lean.toPerception().fruit()).containsExactly(
                new PerceivedFruit("F1", FruitKind.COCONUT, new Vec3(1, 0.35, -2), 0.35, null));
    }

    @Test
    void aHelloNamesTheFormsItReadsAndUnknownNamesMeanNothing() {
        HelloMessage hello = new HelloMessage(1, 2, Role.AGENT, "lean", null, null,
                List.of("LeanPerception", "Telepathy"));
        HelloMessage decoded = (HelloMessage) codec.decode(codec.encode(hello));
        assertThat(decoded).isEqualTo(hello);
        assertThat(codec.encode(hello)).endsWith(",\"reads\":[\"LeanPerception\",\"Telepathy\"]}");
        assertThat(Form.named(decoded.reads())).containsExactly(Form.LEAN_PERCEPTION);
        assertThat(Form.named(null)).isEmpty();
        assertThat(Form.names(Set.of(Form.ACCEPTED_MOVES, Form.LEAN_PERCEPTION)))
                .containsExactly("LeanPerception", "AcceptedMoves");
        assertThat(Form.names(Set.of())).isEmpty();
    }

    @Test
    void aHelloReadsAtMostSixteenFormsEachNamedAsANameIs() {
        assertThatThrownBy(() -> codec.decodeClient("{\"type\":\"Hello\",\"seq\":1,\"protocolVersion\":2,"
                + "\"role\":\"agent\",\"client\":\"x\",\"reads\":[\"no spaces\"]}"))
                .isInstanceOf(ProtocolException.class).hasMessageContaining("reads[0] must be a letter");
        List<String> many = new ArrayList<>();
        for (int i = 0; i < 17; i++) {
            many.add("F" + i);
        }
        assertThatThrownBy(() -> new HelloMessage(1, 2, Role.AGENT, "x", null, null, many))
                .hasMessage("reads must name at most 16 forms, named 17");
    }

    // ---- perceptions as the server makes them ---------------------------------------------------

    private double centimetres(double range) {
        return Math.round((random.nextDouble() - 0.5) * 2 * range * 100) / 100.0;
    }

    private double distance() {
        return Math.round(random.nextDouble() * 60 * 100) / 100.0;
    }

    /** An angle as the server rounds it: to 0.001, in (-π, π], with π itself now and then. */
    private double angle() {
        if (random.nextInt(20) == 0) {
            return Math.PI;
        }
        double rounded = Math.round((random.nextDouble() - 0.5) * 2 * Math.PI * 1000) / 1000.0;
        return rounded <= -Math.PI ? rounded + 0.001 : Math.min(rounded, Math.PI);
    }

    /** A size as a scenario may give it, not rounded. */
    private double size() {
        return 0.005 + random.nextDouble() * (random.nextBoolean() ? 2 : 20);
    }

    private RelativePosition at() {
        return new RelativePosition(distance(), angle());
    }

    private PerceptionMessage perception(long tick) {
        List<PerceivedObject> objects = new ArrayList<>();
        for (int i = random.nextInt(30); i > 0; i--) {
            objects.add(new PerceivedObject("T" + random.nextInt(10_000), random.nextBoolean() ? ObjectKind.TREE
                    : ObjectKind.TABLE, at(), size(), size()));
        }
        List<PerceivedAgent> agents = new ArrayList<>();
        for (int i = random.nextInt(5); i > 0; i--) {
            agents.add(new PerceivedAgent("A" + random.nextInt(1000), at(), angle(), size()));
        }
        List<PerceivedFruit> fruit = new ArrayList<>();
        for (int i = random.nextInt(8); i > 0; i--) {
            FruitKind kind = FruitKind.values()[random.nextInt(3)];
            fruit.add(new PerceivedFruit("F" + random.nextInt(2000), kind, new Vec3(centimetres(10_000),
                    Math.abs(centimetres(4)), centimetres(10_000)), kind.radius(), random.nextBoolean() ? null : "D3"));
        }
        return new PerceptionMessage(tick, "Guppy", new Vec3(centimetres(10_000), 0, centimetres(10_000)), angle(),
                objects, agents, fruit);
    }

    private LandmarkPerceptionMessage landmarks(long tick) {
        PerceivedRiver river = random.nextBoolean() ? null : new PerceivedRiver(at(), angle());
        List<PerceivedBridge> bridges = new ArrayList<>();
        for (int i = random.nextInt(3); i > 0; i--) {
            bridges.add(new PerceivedBridge("B" + i, at(), at(), size()));
        }
        return new LandmarkPerceptionMessage(tick, "Guppy", river, bridges);
    }

    private static double cm(double size) {
        return LeanUnits.size(size) / 100.0;
    }

    private static PerceptionMessage sizesInCentimetres(PerceptionMessage m) {
        return new PerceptionMessage(m.tick(), m.agent(), m.position(), m.heading(),
                m.objects().stream().map(o -> new PerceivedObject(o.id(), o.kind(), o.at(), cm(o.radius()),
                        cm(o.height()))).toList(),
                m.agents().stream().map(a -> new PerceivedAgent(a.name(), a.at(), a.heading(), cm(a.radius()))).toList(),
                m.fruit());
    }

    private static LandmarkPerceptionMessage sizesInCentimetres(LandmarkPerceptionMessage m) {
        return new LandmarkPerceptionMessage(m.tick(), m.agent(), m.river(), m.bridges().stream()
                .map(b -> new PerceivedBridge(b.id(), b.entryA(), b.entryB(), cm(b.width()))).toList());
    }
}
