package io.orchard.server.world;

import io.orchard.protocol.value.Bounds;
import io.orchard.protocol.value.ObjectKind;
import io.orchard.protocol.value.Obstacle;
import io.orchard.protocol.value.Point2;
import java.util.ArrayList;
import java.util.List;
import java.util.random.RandomGenerator;

/**
 * Places the trees and tables of a generated world, each with the clearances
 * {@link WorldGenerator} documents: most trees in a forest, the rest and the tables anywhere there
 * is room. A candidate that does not fit is drawn again, up to a limit.
 */
final class Grove {

    private static final int ATTEMPTS = 300;

    private final RandomGenerator random;
    private final Bounds bounds;
    private final Region castle;
    private final Region river;
    private final List<Region> decks;
    private final Crowd crowd = new Crowd();

    Grove(RandomGenerator random, Bounds bounds, Region castle, Region river, List<Region> decks) {
        this.random = random;
        this.bounds = bounds;
        this.castle = castle;
        this.river = river;
        this.decks = decks;
    }

    List<Obstacle> trees(int count, Point2 castleCentre) {
        int inForest = (int) Math.round(count * WorldGenerator.FOREST_SHARE);
        double forestRadius = Math.max(10, Math.sqrt(inForest * WorldGenerator.FOREST_AREA_PER_TREE / Math.PI));
        Point2 forest = forestCentre(forestRadius, castleCentre);
        List<Obstacle> trees = new ArrayList<>(count);
        for (int i = 1; i <= count; i++) {
            String id = "T" + i;
            boolean dense = i <= inForest;
            Obstacle tree = null;
            for (int attempt = 0; attempt < ATTEMPTS && tree == null; attempt++) {
                Point2 at = dense && attempt < ATTEMPTS / 2 ? inDisc(forest, forestRadius) : anywhere();
                double crown = RiverLayout.round(uniform(1.5, 3.0));
                double height = RiverLayout.round(uniform(4.5, 8.0));
                double trunk = Tree.trunkRadius(crown);
                if (fits(at, trunk, WorldGenerator.TREE_CLEARANCE)) {
                    crowd.add(at.x(), at.z(), trunk);
                    tree = new Obstacle(id, ObjectKind.TREE, at, crown, height);
                }
            }
            trees.add(placed(tree, "tree " + id));
        }
        return trees;
    }

    List<Obstacle> tables(int count) {
        List<Obstacle> tables = new ArrayList<>(count);
        for (int i = 1; i <= count; i++) {
            String id = "D" + i;
            Obstacle table = null;
            for (int attempt = 0; attempt < ATTEMPTS && table == null; attempt++) {
                Point2 at = anywhere();
                double radius = RiverLayout.round(uniform(0.6, 1.0));
                double height = RiverLayout.round(uniform(0.7, 1.0));
                if (fits(at, radius, WorldGenerator.TABLE_CLEARANCE)) {
                    crowd.add(at.x(), at.z(), radius);
                    table = new Obstacle(id, ObjectKind.TABLE, at, radius, height);
                }
            }
            tables.add(placed(table, "table " + id));
        }
        return tables;
    }

    private Obstacle placed(Obstacle obstacle, String name) {
        if (obstacle == null) {
            throw new IllegalStateException("could not place " + name + " after " + ATTEMPTS
                    + " attempts: the world is too crowded; ask for fewer trees and tables or a larger world");
        }
        return obstacle;
    }

    /** A centre for the forest on land, away from the castle; the trees that land in the river move on. */
    private Point2 forestCentre(double radius, Point2 castleCentre) {
        Point2 best = anywhere();
        for (int attempt = 0; attempt < 100; attempt++) {
            Point2 candidate = new Point2(
                    uniform(bounds.minX() + radius / 2, bounds.maxX() - radius / 2),
                    uniform(bounds.minZ() + radius / 2, bounds.maxZ() - radius / 2));
            best = candidate;
            if (candidate.distance(castleCentre) > radius + 15
                    && !river.touchedBy(candidate.x(), candidate.z(), candidate.x(), candidate.z(), 5)) {
                break;
            }
        }
        return best;
    }

    private boolean fits(Point2 at, double radius, double clearance) {
        double x = at.x();
        double z = at.z();
        double edge = radius + WorldGenerator.EDGE_CLEARANCE;
        return x - edge >= bounds.minX() && x + edge <= bounds.maxX()
                && z - edge >= bounds.minZ() && z + edge <= bounds.maxZ()
                && crowd.keepsClear(x, z, radius, clearance)
                && !castle.touchedBy(x, z, x, z, radius + clearance)
                && !river.touchedBy(x, z, x, z, radius + WorldGenerator.RIVER_CLEARANCE)
                && decks.stream().noneMatch(deck -> deck.touchedBy(x, z, x, z, radius + WorldGenerator.BRIDGE_CLEARANCE));
    }

    private Point2 anywhere() {
        return new Point2(RiverLayout.round(uniform(bounds.minX(), bounds.maxX())),
                RiverLayout.round(uniform(bounds.minZ(), bounds.maxZ())));
    }

    private Point2 inDisc(Point2 centre, double radius) {
        double r = radius * Math.sqrt(random.nextDouble());
        double angle = uniform(0, 2 * Math.PI);
        return new Point2(RiverLayout.round(centre.x() + r * StrictMath.cos(angle)),
                RiverLayout.round(centre.z() + r * StrictMath.sin(angle)));
    }

    private double uniform(double from, double to) {
        return from + (to - from) * random.nextDouble();
    }
}
