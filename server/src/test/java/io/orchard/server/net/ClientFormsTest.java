package io.orchard.server.net;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.message.ActionResultMessage;
import io.orchard.protocol.message.HelloMessage;
import io.orchard.protocol.value.Outcome;
import io.orchard.protocol.value.Role;
import io.orchard.protocol.value.Vec3;
import java.util.List;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** What a hello's {@code reads} asks for, and which results a client then does without. */
class ClientFormsTest {

    private static final ActionResultMessage ACCEPTED_MOVE = new ActionResultMessage(6, "Guppy", "Move",
            Outcome.ACCEPTED, null, Vec3.ZERO, 0.5);
    private static final ActionResultMessage BLOCKED_MOVE = new ActionResultMessage(6, "Guppy", "Move",
            Outcome.BLOCKED, "agent Bunny is in the way", Vec3.ZERO, 0.2);
    private static final ActionResultMessage REJECTED_MOVE = new ActionResultMessage(6, "Guppy", "Move",
            Outcome.REJECTED, "path crosses tree T17", null, 0);
    private static final ActionResultMessage ACCEPTED_REQUEST = new ActionResultMessage(7, "Guppy",
            "PerceptionRequest", Outcome.ACCEPTED, null, null, 0);

    @ParameterizedTest(name = "version {0} reading [{1}]")
    @CsvSource(delimiter = '|', nullValues = "-", textBlock = """
        1 | LeanPerception                | false | true
        2 | -                             | false | true
        2 | Telepathy                     | false | true
        2 | LeanPerception                | true  | false
        2 | LeanPerception Telepathy      | true  | false
        2 | AcceptedMoves                 | false | true
        2 | AcceptedMoves LeanPerception  | true  | true
        """)
    void aHelloGetsTheFormsItNames(int version, String reads, boolean lean, boolean acceptedMoves) {
        HelloMessage hello = new HelloMessage(1, version, Role.AGENT, "test", null, null,
                reads == null ? null : List.of(reads.split(" ")));
        ClientForms forms = ClientForms.of(hello);
        assertThat(forms).isEqualTo(new ClientForms(lean, acceptedMoves));
        assertThat(forms.sends(ACCEPTED_MOVE)).isEqualTo(acceptedMoves);
        assertThat(forms.sends(BLOCKED_MOVE)).isTrue();
        assertThat(forms.sends(REJECTED_MOVE)).isTrue();
        assertThat(forms.sends(ACCEPTED_REQUEST)).isTrue();
    }
}
