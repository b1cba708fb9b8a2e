package io.orchard.server;

import io.orchard.server.net.NetServer;
import io.orchard.server.sim.Checkpoint;
import io.orchard.server.sim.GameListener;
import io.orchard.server.sim.Phase;
import io.orchard.server.sim.Recorder;
import io.orchard.server.sim.Simulation;
import io.orchard.server.sim.SimulationConfig;
import io.orchard.server.sim.TickLoop;
import io.orchard.server.world.scenario.Scenario;
import io.orchard.server.world.World;
import io.orchard.server.world.WorldGenerator;
import java.io.IOException;
import java.net.InetSocketAddress;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ThreadLocalRandom;
import java.util.function.LongFunction;

/**
 * Puts a {@link WorldServer} together from its builder's settings, in order: the game (new, or
 * continued from a checkpoint), its recording and checkpoints, the network, and the tick thread.
 * What was opened is closed again when the network cannot start.
 */
final class Startup {

    private Startup() {}

    static WorldServer start(WorldServer.Builder settings) throws IOException {
        GameFiles.removeLeftovers(settings.checkpointFile);
        GameFiles.removeLeftovers(settings.resume);
        Checkpoint saved = settings.resume != null ? GameFiles.checkpoint(settings.resume) : null;
        long actualSeed = saved != null ? saved.seed()
                : settings.seed != null ? settings.seed : ThreadLocalRandom.current().nextLong(1, 1L << 48);
        Scenario scenario = settings.scenario != null ? GameFiles.scenario(settings.scenario) : null;
        // A restarted game's world: the scenario's again, or the one its seed makes.
        LongFunction<World> worlds = scenario != null ? seed -> World.fromScenario(scenario)
                : seed -> WorldGenerator.standard(seed).generate();
        World world = saved != null ? World.fromScenario(saved.world()) : worlds.apply(actualSeed);
        SimulationConfig config = saved != null
                ? new SimulationConfig(saved.tickRate(), saved.clock(), saved.timeLimit(), saved.waitFor(),
                        settings.lockstepDeadline, SimulationConfig.DEFAULT.agentsPerSession(),
                        SimulationConfig.DEFAULT.bodyLimits())
                : new SimulationConfig(settings.tickRate, settings.clock, settings.timeLimit, settings.waitFor,
                        settings.lockstepDeadline, SimulationConfig.DEFAULT.agentsPerSession(),
                        SimulationConfig.DEFAULT.bodyLimits());
        Recorder recorder = settings.record != null ? GameFiles.recorder(settings.record, saved != null)
                : Recorder.NONE;
        GameResults over = new GameResults();
        List<GameListener> all = new ArrayList<>(settings.listeners);
        all.add(over);
        Simulation simulation = new Simulation(world, config, actualSeed, Version.current(), recorder, all,
                settings.placement);
        simulation.reserveDroppedNames(settings.nameReservation);
        if (saved != null) {
            simulation.restore(saved);
            if (simulation.phase() == Phase.OVER) {
                over.gameOver("over when saved", simulation.ranking());
            }
        }
        if (settings.oneGame != null) {
            simulation.oneGameOnly(settings.oneGame);
        } else if (settings.record != null || settings.checkpointFile != null || saved != null) {
            simulation.oneGameOnly("this server plays one game: it " + (settings.record != null ? "records it"
                    : saved != null ? "continues a saved one" : "saves it to a checkpoint file")
                    + "; start a server for each game instead");
        } else {
            simulation.restartsWith(worlds);
        }
        Checkpoints checkpoints = new Checkpoints(settings.checkpointFile);
        if (settings.checkpointFile != null) {
            simulation.checkpointWhenScored(checkpoints::offer);
        }
        NetServer net;
        try {
            net = NetServer.start(new InetSocketAddress(settings.bind, settings.port), simulation, settings.token,
                    settings.operatorToken, settings.limits);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            recorder.close();
            checkpoints.close();
            throw new IOException("interrupted while binding port " + settings.port, e);
        } catch (IOException e) {
            recorder.close();
            checkpoints.close();
            throw e;
        } catch (RuntimeException e) {
            recorder.close();
            checkpoints.close();
            throw new IOException("cannot listen on " + settings.bind + ":" + settings.port + ": " + e.getMessage(),
                    e);
        }
        WebFrontEnd.Serving web = null;
        if (settings.httpPort != null) {
            try {
                web = WebPage.serve(new InetSocketAddress(settings.bind, settings.httpPort), net.address());
            } catch (IOException | RuntimeException e) {
                net.close();
                recorder.close();
                checkpoints.close();
                throw e;
            }
        }
        TickLoop loop = new TickLoop(simulation);
        Thread thread = new Thread(loop, "orchard-tick");
        // The one thread the game waits for comes first. (The JVM passes this on to the system only
        // where it may: on Linux with -XX:ThreadPriorityPolicy=1, as root.)
        thread.setPriority(Thread.MAX_PRIORITY);
        thread.start();
        if (settings.checkpointFile != null && settings.checkpointEvery != null) {
            checkpoints.every(settings.checkpointEvery, () -> simulation.checkpointAtTickEnd(
                    state -> checkpoints.write(state, settings.checkpointFile, null)));
        }
        return new WorldServer(simulation, net, loop, thread, recorder, over, checkpoints, web);
    }
}
