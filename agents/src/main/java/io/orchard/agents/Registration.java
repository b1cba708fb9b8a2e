package io.orchard.agents;

import io.orchard.protocol.message.ErrorMessage;
import io.orchard.protocol.message.RegisterMessage;
import io.orchard.protocol.message.Reply;
import io.orchard.protocol.value.ModelSpec;
import io.orchard.protocol.value.Nullable;
import java.io.IOException;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;

/**
 * Registering an agent: its model read from the resources next to its class and checked against
 * the joints and time sensors it declares, before it connects; then its body and model registered,
 * failing with the server's reason, or when no answer comes in time.
 */
final class Registration {

    private static final long REPLY_TIMEOUT_SECONDS = 10;

    private Registration() {}

    /**
     * The agent's model, read and checked; null when it has none.
     *
     * @throws ModelCheckException when the model lacks a node the agent registers
     */
    static @Nullable ModelSpec model(Class<?> owner, String agent, AgentBody plan) throws IOException {
        if (plan.model() == null) {
            return null;
        }
        AgentModel model = AgentModel.load(owner, plan.model());
        if (plan.modelName() != null) {
            model = model.renamed(plan.modelName(), agent);
        }
        model.check(agent, plan.joints(), plan.timeSensors());
        return model.spec();
    }

    /**
     * Registers the agent's body and model, presenting {@code resumeToken} (if any) to get back an
     * agent of an earlier connection, and waits for the server to accept them.
     */
    static void register(Session session, String agent, AgentBody plan, @Nullable ModelSpec model,
                         @Nullable String resumeToken) throws IOException, InterruptedException {
        Reply reply;
        try {
            reply = session.request(seq -> new RegisterMessage(seq, agent, plan.body(), model, resumeToken))
                    .get(REPLY_TIMEOUT_SECONDS, TimeUnit.SECONDS);
        } catch (ExecutionException e) {
            throw new IOException("registration of " + agent + " failed: " + e.getCause().getMessage(), e.getCause());
        } catch (TimeoutException e) {
            throw new IOException("no answer to the registration of " + agent + " within " + REPLY_TIMEOUT_SECONDS + " s");
        }
        if (reply instanceof ErrorMessage error) {
            throw new IOException("the server refused to register " + agent + ": " + error.code().wireName() + ": "
                    + error.text());
        }
    }
}
