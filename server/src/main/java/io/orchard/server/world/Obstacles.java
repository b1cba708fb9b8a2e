package io.orchard.server.world;

import io.orchard.protocol.value.Bounds;
import io.orchard.protocol.value.ObjectKind;
import io.orchard.protocol.value.Obstacle;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

/**
 * The trees and tables of a world in parallel arrays, with a grid over their centres: what
 * collision and perception read many times per tick. Item {@code i} is tree {@code i} when
 * {@code i < trees.size()}, else table {@code i - trees.size()}.
 *
 * <p>The blocking radius of an item is its trunk's for a tree and its top's for a table. The
 * protocol records are made once here, so that perception hands out the same instances every tick.
 *
 * <p>Immutable.
 */
final class Obstacles {

    final List<Tree> trees;
    final List<Table> tables;
    final double[] x;
    final double[] z;
    final double[] blockRadius;
    final Obstacle[] records;
    final double maxBlockRadius;
    final CircleGrid grid;
    private final Map<String, Integer> byId = new HashMap<>();

    Obstacles(Bounds bounds, List<Tree> trees, List<Table> tables) {
        this.trees = List.copyOf(trees);
        this.tables = List.copyOf(tables);
        int count = trees.size() + tables.size();
        this.x = new double[count];
        this.z = new double[count];
        this.blockRadius = new double[count];
        this.records = new Obstacle[count];
        double widest = 0;
        for (int i = 0; i < count; i++) {
            if (i < trees.size()) {
                Tree tree = trees.get(i);
                x[i] = tree.position().x();
                z[i] = tree.position().z();
                blockRadius[i] = tree.trunkRadius();
                records[i] = tree.obstacle();
            } else {
                Table table = tables.get(i - trees.size());
                x[i] = table.position().x();
                z[i] = table.position().z();
                blockRadius[i] = table.radius();
                records[i] = table.obstacle();
            }
            widest = Math.max(widest, blockRadius[i]);
            byId.putIfAbsent(records[i].id(), i);
        }
        this.maxBlockRadius = widest;
        this.grid = new CircleGrid(bounds, x, z);
    }

    int size() {
        return records.length;
    }

    boolean isTree(int item) {
        return item < trees.size();
    }

    ObjectKind kind(int item) {
        return records[item].kind();
    }

    String id(int item) {
        return records[item].id();
    }

    Optional<Integer> indexOf(String id) {
        return Optional.ofNullable(byId.get(id));
    }

    /** A name for people: "tree T3", "table D1". */
    String describe(int item) {
        return (isTree(item) ? "tree " : "table ") + id(item);
    }
}
