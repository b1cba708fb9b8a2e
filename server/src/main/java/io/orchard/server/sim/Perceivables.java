package io.orchard.server.sim;

import io.orchard.protocol.value.FruitState;
import io.orchard.protocol.value.Obstacle;
import io.orchard.protocol.value.PerceivedFruit;
import io.orchard.server.world.World;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Function;

/**
 * The things of a world that a {@link Percept} names by their index: the trees and tables, and
 * every fruit the world was made with as an agent perceives it (a fruit never moves, so its
 * perceived record is made once, here). Whatever a writer of perceptions derives from them once
 * for every perception (the lean form's tuples, already encoded) is kept here too, so that it lives
 * as long as the world does.
 *
 * <p>Immutable once made, and safe to read from any thread: the simulation's thread makes the
 * perceptions, the network threads write them.
 */
public final class Perceivables {

    private final Obstacle[] obstacles;
    private final PerceivedFruit[] fruit;
    private final Map<Class<?>, Object> derived = new ConcurrentHashMap<>();

    Perceivables(World world) {
        this.obstacles = world.obstacles().toArray(Obstacle[]::new);
        List<FruitState> states = world.allFruitStates();
        this.fruit = new PerceivedFruit[states.size()];
        for (int i = 0; i < fruit.length; i++) {
            FruitState state = states.get(i);
            fruit[i] = new PerceivedFruit(state.id(), state.kind(), Precision.position(state.position()),
                    state.kind().radius(), state.support());
        }
    }

    /** How many trees and tables there are. */
    public int obstacles() {
        return obstacles.length;
    }

    /** The tree or table with this index. */
    public Obstacle obstacle(int index) {
        return obstacles[index];
    }

    /** How many fruit the world was made with. */
    public int fruit() {
        return fruit.length;
    }

    /** The fruit with this index as an agent perceives it, its position rounded to centimetres. */
    public PerceivedFruit fruit(int index) {
        return fruit[index];
    }

    /**
     * What {@code make} derives from these things, made on the first call for its type and kept:
     * every later call for the same type returns the same object, from any thread.
     */
    public <T> T derived(Class<T> type, Function<Perceivables, T> make) {
        Object made = derived.get(type);
        return type.cast(made != null ? made : derived.computeIfAbsent(type, t -> make.apply(this)));
    }
}
