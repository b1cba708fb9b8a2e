package io.orchard.server.world;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * The circles placed so far while a world is generated, in a hash grid, to answer "does a new
 * circle keep its distance from all of them?" without looking at every one: a benchmark world
 * places ten thousand.
 */
final class Crowd {

    private static final double CELL = 8;

    private final Map<Long, List<double[]>> cells = new HashMap<>();
    private double widest;

    /** Whether a circle at (x, z) of radius r keeps {@code gap} from the edge of every circle placed. */
    boolean keepsClear(double x, double z, double r, double gap) {
        double reach = r + gap + widest;
        int firstColumn = cell(x - reach);
        int lastColumn = cell(x + reach);
        int firstRow = cell(z - reach);
        int lastRow = cell(z + reach);
        for (int column = firstColumn; column <= lastColumn; column++) {
            for (int row = firstRow; row <= lastRow; row++) {
                List<double[]> placed = cells.get(key(column, row));
                if (placed == null) {
                    continue;
                }
                for (double[] circle : placed) {
                    double limit = r + circle[2] + gap;
                    double dx = circle[0] - x;
                    double dz = circle[1] - z;
                    if (dx * dx + dz * dz < limit * limit) {
                        return false;
                    }
                }
            }
        }
        return true;
    }

    void add(double x, double z, double r) {
        cells.computeIfAbsent(key(cell(x), cell(z)), k -> new ArrayList<>()).add(new double[] {x, z, r});
        widest = Math.max(widest, r);
    }

    private static int cell(double coordinate) {
        return (int) Math.floor(coordinate / CELL);
    }

    private static long key(int column, int row) {
        return ((long) column << 32) ^ (row & 0xffffffffL);
    }
}
