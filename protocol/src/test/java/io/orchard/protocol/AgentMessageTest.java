package io.orchard.protocol;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.message.AgentMessage;
import io.orchard.protocol.message.ClientMessage;
import io.orchard.protocol.message.InstructionMessage;
import java.lang.reflect.RecordComponent;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Which messages are about one agent, so that a server and a viewer find the agent the same way. */
class AgentMessageTest {

    /** A client action left out would reach no agent on the server. */
    @Test
    void theClientMessagesAboutAnAgentAreThoseThatNameOneButAnInstruction() {
        List<String> naming = MessageTypes.all().entrySet().stream()
                .filter(type -> ClientMessage.class.isAssignableFrom(type.getValue()))
                .filter(type -> type.getValue() != InstructionMessage.class)
                .filter(type -> Arrays.stream(type.getValue().getRecordComponents()).map(RecordComponent::getName)
                        .anyMatch("agent"::equals))
                .map(java.util.Map.Entry::getKey).toList();
        List<String> about = MessageTypes.all().entrySet().stream()
                .filter(type -> ClientMessage.class.isAssignableFrom(type.getValue()))
                .filter(type -> AgentMessage.class.isAssignableFrom(type.getValue()))
                .map(java.util.Map.Entry::getKey).toList();
        assertThat(about).containsExactlyElementsOf(naming).contains("Move", "Unregister", "GraspRequest", "Say");
    }
}
