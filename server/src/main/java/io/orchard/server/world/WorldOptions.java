package io.orchard.server.world;

import io.orchard.protocol.value.Checks;

/**
 * What {@link WorldGenerator} makes: a square world of {@code size} units a side, centred on the
 * origin, with this many trees, tables and fruit. Every world also gets one river across it, two
 * bridges over the river and a castle. Immutable; the constructor refuses what could not be built.
 *
 * @param size   the length of the world's side, in units (about metres); at least
 *               {@value #MIN_SIZE}, at most {@value #MAX_SIZE}
 * @param trees  how many trees; about 60 % of them stand together in the forest
 * @param tables how many tables
 * @param fruit  how many fruit: about 40 % on the ground, 30 % on tables and 30 % in trees
 */
public record WorldOptions(double size, int trees, int tables, int fruit) {

    /** The smallest world: room for the river, two bridges and the castle. */
    public static final double MIN_SIZE = 100;

    /** The largest world. */
    public static final double MAX_SIZE = 10_000;

    /** Ground area per tree or table at the most crowded; more would leave agents no way through. */
    public static final double MIN_AREA_PER_OBSTACLE = 50;

    /** Ground area per fruit at the most crowded. */
    public static final double MIN_AREA_PER_FRUIT = 50;

    /** The paper's garden: 200 x 200 units, 40 trees, 6 tables, 30 fruit. */
    public static final WorldOptions DEFAULT = new WorldOptions(200, 40, 6, 30);

    /** A world for benchmarks: 1,000 x 1,000 units with 10,000 objects (7,000 trees, 1,000 tables, 2,000 fruit). */
    public static final WorldOptions BENCHMARK = new WorldOptions(1000, 7000, 1000, 2000);

    /** Checks the components; a bad value is refused with an exception that names it. */
    public WorldOptions {
        Checks.finite(size, "size");
        if (size < MIN_SIZE || size > MAX_SIZE) {
            throw new IllegalArgumentException("size must be between " + (int) MIN_SIZE + " and " + (int) MAX_SIZE
                    + " units, was " + size);
        }
        Checks.nonNegative(trees, "trees");
        Checks.nonNegative(tables, "tables");
        Checks.nonNegative(fruit, "fruit");
        double area = size * size;
        long obstacles = (long) trees + tables;
        if (obstacles > area / MIN_AREA_PER_OBSTACLE) {
            throw new IllegalArgumentException("too many trees and tables for a world of " + size + " x " + size + ": "
                    + obstacles + " asked, at most " + (long) (area / MIN_AREA_PER_OBSTACLE));
        }
        if (fruit > area / MIN_AREA_PER_FRUIT) {
            throw new IllegalArgumentException("too much fruit for a world of " + size + " x " + size + ": " + fruit
                    + " asked, at most " + (long) (area / MIN_AREA_PER_FRUIT));
        }
    }

    /** These options with a world {@code newSize} units square. */
    public WorldOptions withSize(double newSize) {
        return new WorldOptions(newSize, trees, tables, fruit);
    }

    /** These options with {@code count} trees. */
    public WorldOptions withTrees(int count) {
        return new WorldOptions(size, count, tables, fruit);
    }

    /** These options with {@code count} tables. */
    public WorldOptions withTables(int count) {
        return new WorldOptions(size, trees, count, fruit);
    }

    /** These options with {@code count} pieces of fruit. */
    public WorldOptions withFruit(int count) {
        return new WorldOptions(size, trees, tables, count);
    }
}
