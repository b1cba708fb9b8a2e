package io.orchard.server.sim;

import java.util.Collection;

/**
 * The agents where they stand at one moment, for the perceptions of a tick: a dense grid over the
 * cells the agents occupy, each cell's agents and their coordinates next to each other in memory,
 * so that a query reads a few runs of arrays instead of looking each cell up in a table and
 * following every agent to its position. It does not follow moves ({@link AgentGrid} does).
 *
 * <p>A query visits the agents exactly as {@link AgentGrid#forEachInBox} does over cells of the
 * same size: column by column from west to east, each column's cells from north to south, each
 * cell's agents in the order they were given (by name), so the perceptions it makes are the same.
 * Agents spread over so many cells that the dense grid would be much larger than the crowd are
 * left to an {@link AgentGrid}, which {@link #of} makes instead.
 */
final class CrowdGrid {

    /** Receives an agent with its position on the ground, read from the grid's own copy. */
    interface Visitor {
        void agent(Agent agent, double x, double z);
    }

    /** A grid of either kind, queried alike. */
    interface Query {
        void forEachInBox(double minX, double minZ, double maxX, double maxZ, Visitor visitor);
    }

    private final double cell;
    private final int minColumn;
    private final int minRow;
    private final int columns;
    private final int rows;
    /**
     * Cell (column, row) holds items {@code start[c]} up to {@code start[c + 1]}, where
     * c = (column - minColumn) * rows + row - minRow.
     */
    private final int[] start;
    private final Agent[] agents;
    private final double[] x;
    private final double[] z;

    private CrowdGrid(Agent[] byName, double cell, int minColumn, int minRow, int columns, int rows, int[] cellOf) {
        this.cell = cell;
        this.minColumn = minColumn;
        this.minRow = minRow;
        this.columns = columns;
        this.rows = rows;
        this.start = new int[columns * rows + 1];
        for (int c : cellOf) {
            start[c + 1]++;
        }
        for (int c = 0; c < columns * rows; c++) {
            start[c + 1] += start[c];
        }
        int[] fill = java.util.Arrays.copyOf(start, columns * rows);
        this.agents = new Agent[byName.length];
        this.x = new double[byName.length];
        this.z = new double[byName.length];
        for (int i = 0; i < byName.length; i++) {
            int k = fill[cellOf[i]]++;
            agents[k] = byName[i];
            x[k] = byName[i].position.x();
            z[k] = byName[i].position.z();
        }
    }

    /**
     * The agents, given in the order of their names, in cells of {@code cell} units: a dense grid,
     * or an {@link AgentGrid} when they are spread over more than a few cells per agent.
     */
    static Query of(Collection<Agent> agents, double cell) {
        Agent[] byName = agents.toArray(Agent[]::new);
        int[] columnOf = new int[byName.length];
        int[] rowOf = new int[byName.length];
        int minColumn = Integer.MAX_VALUE;
        int maxColumn = Integer.MIN_VALUE;
        int minRow = Integer.MAX_VALUE;
        int maxRow = Integer.MIN_VALUE;
        for (int i = 0; i < byName.length; i++) {
            columnOf[i] = index(byName[i].position.x(), cell);
            rowOf[i] = index(byName[i].position.z(), cell);
            minColumn = Math.min(minColumn, columnOf[i]);
            maxColumn = Math.max(maxColumn, columnOf[i]);
            minRow = Math.min(minRow, rowOf[i]);
            maxRow = Math.max(maxRow, rowOf[i]);
        }
        long cells = byName.length == 0 ? 0 : ((long) maxColumn - minColumn + 1) * ((long) maxRow - minRow + 1);
        if (cells > 8L * byName.length + 65_536) {
            AgentGrid sparse = new AgentGrid(agents, cell);
            return (minX, minZ, maxX, maxZ, visitor) -> sparse.forEachInBox(minX, minZ, maxX, maxZ,
                    agent -> visitor.agent(agent, agent.position.x(), agent.position.z()));
        }
        int columns = byName.length == 0 ? 0 : maxColumn - minColumn + 1;
        int rows = byName.length == 0 ? 0 : maxRow - minRow + 1;
        int[] cellOf = new int[byName.length];
        for (int i = 0; i < byName.length; i++) {
            cellOf[i] = (columnOf[i] - minColumn) * rows + rowOf[i] - minRow;
        }
        CrowdGrid grid = new CrowdGrid(byName, cell, minColumn, minRow, columns, rows, cellOf);
        return grid::forEachInBox;
    }

    private static int index(double coordinate, double cell) {
        return (int) Math.floor(coordinate / cell);
    }

    /** Gives every agent filed in a cell that meets the box, with its position. */
    void forEachInBox(double boxMinX, double boxMinZ, double boxMaxX, double boxMaxZ, Visitor visitor) {
        int firstColumn = Math.max(index(boxMinX, cell), minColumn);
        int lastColumn = Math.min(index(boxMaxX, cell), minColumn + columns - 1);
        int firstRow = Math.max(index(boxMinZ, cell), minRow);
        int lastRow = Math.min(index(boxMaxZ, cell), minRow + rows - 1);
        if (firstRow > lastRow) {
            return;
        }
        for (int column = firstColumn; column <= lastColumn; column++) {
            int base = (column - minColumn) * rows - minRow;
            // A column's cells from firstRow to lastRow are consecutive, and so are their agents.
            int end = start[base + lastRow + 1];
            for (int k = start[base + firstRow]; k < end; k++) {
                visitor.agent(agents[k], x[k], z[k]);
            }
        }
    }
}
