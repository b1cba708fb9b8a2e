package io.orchard.cluster.node;

import io.orchard.cluster.game.SplitGame;
import io.orchard.server.sim.Checkpoint;
import io.orchard.server.sim.Recorder;
import java.util.function.BiFunction;
import java.util.function.Function;

/**
 * How a node's tick makes its game, wherever the tick runs.
 *
 * @param fresh   a new game, recorded to the recorder given
 * @param saved   the game saved in a checkpoint, going on, recorded to the recorder given
 * @param records the recording: after what it holds when told true (a game that goes on), anew when
 *                false; {@link Recorder#NONE} when the game is not recorded
 */
public record TickGames(Function<Recorder, SplitGame> fresh, BiFunction<Recorder, Checkpoint, SplitGame> saved,
                        Function<Boolean, Recorder> records) {}
