package io.orchard.examples.match;

import io.orchard.agents.AgentController;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

/**
 * Agents playing one game against a server, each on its own daemon thread of this JVM and its own
 * connection, as separate programs would. {@link #close()} makes every agent leave.
 */
public final class Team implements AutoCloseable {

    private final List<AgentController> agents;
    private final Map<String, Throwable> failures = new ConcurrentHashMap<>();
    private final CountDownLatch done;

    private Team(List<AgentController> agents) {
        this.agents = List.copyOf(agents);
        this.done = new CountDownLatch(agents.size());
    }

    /** Starts these agents against the server at {@code host}:{@code port}. */
    public static Team play(List<AgentController> agents, String host, int port) {
        Team team = new Team(agents);
        for (AgentController agent : team.agents) {
            Thread thread = new Thread(() -> team.run(agent, host, port), "orchard-agent-" + agent.name());
            thread.setDaemon(true); // a stuck agent never keeps the JVM alive
            thread.start();
        }
        return team;
    }

    /** Waits until every agent has stopped playing; returns false when the time ran out first. */
    public boolean await(long timeout, TimeUnit unit) throws InterruptedException {
        return done.await(timeout, unit);
    }

    /** Why agents could not play, one line each ("Dwarf: connection refused"); empty when all played. */
    public List<String> failures() {
        List<String> lines = new ArrayList<>();
        for (AgentController agent : agents) {
            Throwable failure = failures.get(agent.name());
            if (failure != null) {
                lines.add(agent.name() + ": " + (failure.getMessage() == null ? failure : failure.getMessage()));
            }
        }
        return lines;
    }

    /** The agents, in the order given. */
    public List<AgentController> agents() {
        return agents;
    }

    @Override
    public void close() {
        agents.forEach(AgentController::stop);
    }

    private void run(AgentController agent, String host, int port) {
        try {
            agent.run(host, port);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (Exception e) {
            failures.put(agent.name(), e);
        } finally {
            done.countDown();
        }
    }
}
