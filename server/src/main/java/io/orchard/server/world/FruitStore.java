package io.orchard.server.world;

import io.orchard.protocol.value.Bounds;
import io.orchard.protocol.value.FruitState;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

/**
 * The fruit of a world: the only part that changes. Fruit never moves and is never added during a
 * game, it is only taken, so the arrays and the grid are built once and a taken fruit is merely
 * marked gone.
 *
 * <p>Not thread-safe: it belongs to the world's owner thread.
 */
final class FruitStore {

    private final Fruit[] fruit;
    private final FruitState[] states;
    private final double[] x;
    private final double[] z;
    private final boolean[] present;
    private final Map<String, Integer> byId = new HashMap<>();
    private final CircleGrid grid;
    private int remaining;

    FruitStore(Bounds bounds, List<Fruit> all) {
        int count = all.size();
        this.fruit = all.toArray(Fruit[]::new);
        this.states = new FruitState[count];
        this.x = new double[count];
        this.z = new double[count];
        this.present = new boolean[count];
        for (int i = 0; i < count; i++) {
            states[i] = fruit[i].state();
            x[i] = fruit[i].position().x();
            z[i] = fruit[i].position().z();
            present[i] = true;
            byId.putIfAbsent(fruit[i].id(), i);
        }
        this.remaining = count;
        this.grid = new CircleGrid(bounds, x, z);
    }

    /** A store sharing this one's fruit and index, with the fruit still there as this one has them now. */
    private FruitStore(FruitStore from) {
        this.fruit = from.fruit;
        this.states = from.states;
        this.x = from.x;
        this.z = from.z;
        this.present = from.present.clone();
        this.grid = from.grid;
        this.byId.putAll(from.byId);
        this.remaining = from.remaining;
    }

    /** A store of its own with the fruit this one has now: taking from one leaves the other's. */
    FruitStore copy() {
        return new FruitStore(this);
    }

    int remaining() {
        return remaining;
    }

    Optional<Fruit> get(String id) {
        Integer index = byId.get(id);
        return index != null && present[index] ? Optional.of(fruit[index]) : Optional.empty();
    }

    boolean remove(String id) {
        Integer index = byId.get(id);
        if (index == null || !present[index]) {
            return false;
        }
        present[index] = false;
        remaining--;
        return true;
    }

    /** The fruit still there, in the order the world was made with. */
    List<Fruit> list() {
        List<Fruit> left = new ArrayList<>(remaining);
        for (int i = 0; i < fruit.length; i++) {
            if (present[i]) {
                left.add(fruit[i]);
            }
        }
        return left;
    }

    List<FruitState> states() {
        List<FruitState> left = new ArrayList<>(remaining);
        for (int i = 0; i < states.length; i++) {
            if (present[i]) {
                left.add(states[i]);
            }
        }
        return left;
    }

    /** Every fruit, taken or not, in the order the world was made with. */
    List<FruitState> allStates() {
        return List.of(states);
    }

    void visitWithin(double cx, double cz, double range, SightBox box, NearbyVisitor visitor) {
        double rangeSq = range * range;
        grid.forEachInBox(box.minX(), box.minZ(), box.maxX(), box.maxZ(), (i, atX, atZ) -> {
            if (present[i]) {
                double dx = atX - cx;
                double dz = atZ - cz;
                double distanceSq = dx * dx + dz * dz;
                if (distanceSq <= rangeSq) {
                    visitor.fruit(i, states[i], atX, atZ, Math.sqrt(distanceSq));
                }
            }
        });
    }
}
