package io.orchard.server.net;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.value.ModelFormat;
import io.orchard.protocol.value.ModelSpec;
import java.util.Base64;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** The caps on models, per connection and in all, and one copy of each model. */
class ModelStoreTest {

    private static final long MIB = 1 << 20;

    private final ModelStore store = new ModelStore(3 * MIB);

    private static ModelSpec model(int size, int fill) {
        byte[] bytes = new byte[size];
        java.util.Arrays.fill(bytes, (byte) fill);
        return ModelSpec.of(ModelFormat.GLB, bytes);
    }

    @ParameterizedTest
    @ValueSource(ints = {0, 1, 2, 3, 4, 5, 1000, 4_194_304})
    void theDecodedSizeIsCountedFromTheText(int size) {
        String data = Base64.getEncoder().encodeToString(new byte[size]);
        assertThat(ModelStore.decodedSize(data)).isEqualTo(size);
        assertThat(ModelStore.decodedSize(Base64.getEncoder().withoutPadding().encodeToString(new byte[size])))
                .isEqualTo(size);
    }

    @Test
    void theSameModelRegisteredAgainIsTheOneCopyAndCostsNothing() {
        ConnectionModels mine = new ConnectionModels();
        ModelSpec first = model((int) MIB, 1);
        ModelSpec again = new ModelSpec(ModelFormat.GLB, null, new String(first.data().toCharArray()));
        assertThat(store.admit(first, mine, 2 * MIB).model()).isSameAs(first);
        ModelStore.Admitted second = store.admit(again, mine, 2 * MIB);
        assertThat(second.model().data()).as("the text kept once").isSameAs(first.data());
        assertThat(mine.bytes()).isEqualTo(MIB);
        assertThat(store.heldBytes()).isEqualTo(MIB);
        ModelStore.Admitted asX3d = store.admit(new ModelSpec(ModelFormat.X3D, null, first.data()), new ConnectionModels(),
                2 * MIB);
        assertThat(asX3d.model().data()).isSameAs(first.data());
        assertThat(store.heldBytes()).isEqualTo(MIB);
    }

    @Test
    void aConnectionMayRegisterSoManyBytesOfModelsInAll() {
        ConnectionModels mine = new ConnectionModels();
        assertThat(store.admit(model((int) MIB, 1), mine, 2 * MIB).refusal()).isNull();
        assertThat(store.admit(model((int) MIB, 2), mine, 2 * MIB).refusal()).isNull();
        assertThat(store.admit(model(10, 3), mine, 2 * MIB).refusal()).isEqualTo("model: a connection may register"
                + " models of at most 2097152 bytes in all, this one has registered 2097152 and this model has 1024");
        assertThat(store.admit(model(10, 3), new ConnectionModels(), 2 * MIB).refusal()).isNull();
    }

    @Test
    void theServerHoldsSoManyBytesOfModelsInAll() {
        ConnectionModels one = new ConnectionModels();
        ConnectionModels two = new ConnectionModels();
        ModelSpec shared = model((int) MIB, 1);
        store.admit(shared, one, 2 * MIB);
        store.admit(model((int) MIB, 2), one, 2 * MIB);
        store.admit(model((int) MIB, 3), two, 2 * MIB);
        assertThat(store.admit(model(1, 4), two, 2 * MIB).refusal()).startsWith(
                "model: the server holds 3145728 bytes of models, and takes at most 3145728; this model has 1024");
        assertThat(store.admit(shared, two, 2 * MIB).refusal()).as("a model already held costs the server nothing").isNull();
        assertThat(two.bytes()).isEqualTo(2 * MIB);
    }
}
