package io.orchard.viewer.replay;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;

class RecordLineTest {

    @Test
    void fieldsAreSplitWithoutDecodingTheMessage() {
        RecordLine line = RecordLine.parse("{\"tick\":12,\"time\":0.6,\"dir\":\"out\",\"to\":\"viewers\","
                + "\"msg\":{\"type\":\"Say\",\"seq\":3,\"agent\":\"Guppy\",\"text\":\"a \\\"quoted\\\" }{ word\"}}");

        assertThat(line.get("tick")).isEqualTo("12");
        assertThat(line.number("time", -1)).isEqualTo(0.6);
        assertThat(line.get("dir")).isEqualTo("out");
        assertThat(line.get("to")).isEqualTo("viewers");
        assertThat(line.get("msg")).startsWith("{\"type\":\"Say\"").endsWith("word\"}");
        assertThat(line.messageType()).isEqualTo("Say");
    }

    @Test
    void fieldOrderDoesNotMatter() {
        RecordLine line = RecordLine.parse(" { \"msg\" : {\"type\":\"Tick\",\"tick\":1,\"time\":0.05} , \"dir\":\"out\" } ");

        assertThat(line.messageType()).isEqualTo("Tick");
        assertThat(line.get("dir")).isEqualTo("out");
        assertThat(line.get("to")).isNull();
    }

    @Test
    void aTruncatedLineIsRefusedWithWhereItEnds() {
        assertThatThrownBy(() -> RecordLine.parse("{\"tick\":12,\"msg\":{\"type\":\"Ti"))
                .isInstanceOf(IllegalArgumentException.class)
                .hasMessageContaining("unexpected end of line");
    }
}
