package io.orchard.server.net;

import static org.assertj.core.api.Assertions.assertThat;

import io.netty.buffer.ByteBuf;
import io.netty.buffer.ByteBufUtil;
import io.orchard.protocol.MessageCodec;
import io.orchard.protocol.message.AgentAddedMessage;
import io.orchard.protocol.value.AgentState;
import io.orchard.protocol.value.Body;
import io.orchard.protocol.value.Gripper;
import io.orchard.protocol.value.ModelFormat;
import io.orchard.protocol.value.ModelSpec;
import io.orchard.protocol.value.Sight;
import io.orchard.protocol.value.Vec3;
import java.util.List;
import org.junit.jupiter.api.Test;

/** An AgentAdded line cut around its model's data and put back together from the shared copy. */
class ModelLinesTest {

    private static final MessageCodec CODEC = new MessageCodec();
    private static final Body BODY = new Body(0.5, 1.2, 10, new Gripper("hands", 0.6, 0, 1.5), new Sight(40, Math.PI));

    private static AgentAddedMessage added(String name, ModelSpec model) {
        return new AgentAddedMessage(12, new AgentState(name, BODY, new Vec3(1, 0, -2.5), 0.25, model,
                List.of("neck", "model"), List.of("\"data\":\"")));
    }

    @Test
    void theThreePiecesAreTheCodecsLineByteForByte() {
        ModelSpec model = ModelSpec.of(ModelFormat.GLB, new byte[] {1, 2, 3, 4, (byte) 0xfb, (byte) 0xff, 0x3f});
        AgentAddedMessage message = added("Guppy", model);
        ModelStore store = new ModelStore(1 << 20);
        ModelLines.Cut cut = ModelLines.cut(CODEC, message);
        ByteBuf data = store.wire(model.data());
        byte[] whole = new byte[cut.before().length + data.readableBytes() + cut.after().length];
        System.arraycopy(cut.before(), 0, whole, 0, cut.before().length);
        data.getBytes(data.readerIndex(), whole, cut.before().length, data.readableBytes());
        System.arraycopy(cut.after(), 0, whole, cut.before().length + data.readableBytes(), cut.after().length);
        data.release();
        assertThat(new String(whole, java.nio.charset.StandardCharsets.UTF_8))
                .isEqualTo(new String(CODEC.encodeLine(message), java.nio.charset.StandardCharsets.UTF_8));
        assertThat(CODEC.decode(whole)).isEqualTo(message);
    }

    @Test
    void onlyModelsWithDataAreCut() {
        assertThat(ModelLines.carriesData(added("Guppy", null))).isFalse();
        assertThat(ModelLines.carriesData(added("Guppy", ModelSpec.bundled("bunny")))).isFalse();
        assertThat(ModelLines.carriesData(added("Guppy", ModelSpec.of(ModelFormat.X3D, new byte[1])))).isTrue();
    }

    @Test
    void everyClientIsGivenTheSameBytesNotACopy() {
        ModelStore store = new ModelStore(1 << 20);
        String data = ModelSpec.of(ModelFormat.GLB, new byte[3000]).data();
        ByteBuf first = store.wire(data);
        ByteBuf second = store.wire(new String(data.toCharArray()));
        assertThat(first.isDirect()).isTrue();
        assertThat(first.memoryAddress()).isEqualTo(second.memoryAddress());
        assertThat(ByteBufUtil.getBytes(first)).isEqualTo(data.getBytes(java.nio.charset.StandardCharsets.US_ASCII));
        first.release();
        second.release();
    }
}
