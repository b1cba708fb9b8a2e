package io.orchard.cluster.node;

import io.orchard.cluster.game.ParcelLost;
import io.orchard.cluster.game.SplitGame;
import io.orchard.protocol.MessageCodec;
import io.orchard.protocol.message.ErrorCode;
import io.orchard.protocol.message.ErrorMessage;
import io.orchard.server.Checkpoints;
import io.orchard.server.sim.Checkpoint;
import io.orchard.server.sim.CheckpointFile;
import io.orchard.server.sim.Phase;
import io.orchard.server.sim.Recorder;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Consumer;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The game on the node where the tick runs, for the tick's whole stay there: the thread that drives
 * its clock ({@link SplitLoop}), its recording, its checkpoints, and its new starts. A game starts
 * new, or from a saved one ({@code --resume}), or, when a tick ran a game before on this cluster (the
 * tick moved here because its node was lost or left), from the cluster-wide checkpoint. When a node
 * is lost, or a parcel does not answer, the whole world rolls back to that checkpoint: every client
 * is told and disconnected (its controller comes back with its resume tokens, to any node), every
 * parcel starts again from the saved world, and the game waits, paused, for its agents, as a server
 * resumed from the checkpoint does. Without a checkpoint file the game starts anew.
 */
final class TickRunner implements SplitLoop.Games {

    private static final Logger log = LoggerFactory.getLogger(TickRunner.class);
    private static final MessageCodec CODEC = new MessageCodec();

    /** How long a rollback waits before trying again when the parcels do not answer yet. */
    private static final Duration RETRY = Duration.ofSeconds(2);

    private final TickGames making;
    private final ShardedParcels parcels;
    private final Path checkpointFile;
    private final Checkpoints checkpoints;
    private final Consumer<GatewayCommand> gateways;
    private final AtomicReference<SplitGame> game = new AtomicReference<>();
    private final SplitLoop loop;
    private final Thread thread;
    private Recorder recorder = Recorder.NONE;
    /** Whether this cluster's game was played to its end before the tick came here: nothing more is recorded. */
    private boolean recordingDone;
    private volatile long epoch;
    /** Why the game must roll back before the next step, or null. */
    private volatile String rollBack;

    /**
     * The tick's game on this node: {@code making} makes it, {@code parcels} reach its parcels, its
     * checkpoints go to {@code checkpointFile} (null: none) when fruit is taken and every
     * {@code checkpointEvery} (null: never), and {@code gateways} reaches every node's gateway.
     */
    TickRunner(TickGames making, ShardedParcels parcels, Path checkpointFile, Duration checkpointEvery,
               Consumer<GatewayCommand> gateways) {
        this.making = making;
        this.parcels = parcels;
        this.checkpointFile = checkpointFile;
        this.checkpoints = new Checkpoints(checkpointFile);
        this.gateways = gateways;
        this.loop = new SplitLoop(this, (phase, tick) -> gateways.accept(new GatewayCommand.Clock(epoch, tick,
                phase.name())));
        this.thread = new Thread(loop, "orchard-split-tick");
        this.thread.setDaemon(true);
        if (checkpointFile != null && checkpointEvery != null) {
            checkpoints.every(checkpointEvery, () -> current().checkpointAtTickEnd(
                    saved -> checkpoints.write(saved, checkpointFile, null)));
        }
    }

    /**
     * Starts the game: from the cluster-wide checkpoint when a tick (the {@code lastEpoch}-th) had a
     * game under way before on this cluster, else from {@code resume} when given, else new. When the
     * tick before had played its game to the end ({@code gameOver}), the new game is not recorded:
     * the recording of the game played is whole, and must not be written over.
     */
    void start(long lastEpoch, boolean gameUnderWay, boolean gameOver, Path resume) {
        recordingDone = gameOver;
        if (gameOver) {
            log.info("the tick came to this node after the game was over: the recording stays as it was, and "
                    + "no other game is recorded");
        }
        epoch = lastEpoch + 1;
        if (checkpointFile != null) {
            try {
                CheckpointFile.removeLeftovers(checkpointFile);
            } catch (IOException e) {
                log.warn("cannot look for unfinished checkpoint writes beside {}: {}", checkpointFile, e.toString());
            }
        }
        if (gameUnderWay) {
            goOn("the node that ran the tick left the cluster");
        } else {
            Checkpoint saved = resume != null ? read(resume) : null;
            use(saved != null ? making.saved().apply(records(true), saved) : making.fresh().apply(records(false)));
        }
        thread.start();
    }

    @Override
    public SplitGame current() {
        return game.get();
    }

    /** A node was lost: what its parcels held is gone, and the world rolls back before the next step. */
    void nodeLost(String why) {
        SplitGame now = current();
        if (now != null && now.inParcels()) { // a game that has not gone to its parcels is all here

            rollBack = why;
            if (parcels != null) {
                parcels.abort(why);
            }
        }
    }

    @Override
    public void failed(ParcelLost lost) throws InterruptedException {
        log.warn("a parcel did not answer: {}", lost.getMessage());
        if (current().inParcels()) {
            rollBack = rollBack != null ? rollBack : lost.getMessage();
        } else {
            pause(); // the game's start asked them, and comes again: nothing of the game is in them yet
        }
    }

    @Override
    public void between() throws InterruptedException {
        String why = rollBack;
        if (why == null) {
            return;
        }
        rollBack = null;
        epoch++;
        pause(); // let the cluster settle: the parcels of a lost node move to the others
        goOn(why);
    }

    /** The world rolls back to the cluster-wide checkpoint (or, without one, starts anew). */
    private void goOn(String why) {
        if (parcels != null) {
            parcels.carryOn();
        }
        recorder.close();
        Checkpoint saved = checkpointFile != null && Files.isRegularFile(checkpointFile) ? read(checkpointFile) : null;
        use(saved != null ? making.saved().apply(records(true), saved) : making.fresh().apply(records(true)));
        String text = saved != null
                ? why + ": the game goes on from its checkpoint of tick " + saved.tick()
                        + "; register your agents again with their resume tokens, at any node"
                : why + " and the game had no checkpoint: a new game starts";
        log.warn("{} (epoch {})", text, epoch);
        gateways.accept(new GatewayCommand.Rollback(epoch, CODEC.encode(new ErrorMessage(0,
                ErrorCode.INTERNAL_ERROR, text))));
    }

    private void use(SplitGame next) {
        if (checkpointFile != null) {
            next.checkpointWhenScored(checkpoints::offer);
        }
        game.set(next);
    }

    private Recorder records(boolean goingOn) {
        recorder = recordingDone ? Recorder.NONE : making.records().apply(goingOn);
        return recorder;
    }

    private static Checkpoint read(Path file) {
        try {
            return CheckpointFile.read(file);
        } catch (IOException e) {
            log.warn("cannot read the checkpoint {}: {}", file, e.getMessage());
            return null;
        }
    }

    /** Asks for a checkpoint at the end of the tick under way, written to the checkpoint file. */
    void checkpointNow() {
        if (checkpointFile != null) {
            current().checkpointAtTickEnd(saved -> checkpoints.write(saved, checkpointFile, null));
        }
    }

    /**
     * Stops the clock after the step under way, saves the game a last time (so that the tick's next
     * node goes on from here) and closes the recording.
     */
    void stop() throws InterruptedException {
        loop.stop();
        thread.join(30_000);
        SplitGame last = current();
        if (checkpointFile != null && last != null && !thread.isAlive() && last.inParcels()
                && last.phase() != Phase.OVER) {
            try {
                CheckpointFile.write(last.checkpoint(), checkpointFile);
            } catch (IOException e) {
                log.warn("cannot save the game to {} as the tick leaves: {}", checkpointFile, e.getMessage());
            }
        }
        checkpoints.close();
        recorder.close();
    }

    /** Waits before a rollback, and between a rollback that found a parcel not answering and the next try. */
    private static void pause() throws InterruptedException {
        Thread.sleep(RETRY.toMillis());
    }
}
