package io.orchard.agents.behaviour;

import java.util.Arrays;

/**
 * A binary min-heap of grid cells keyed by a float cost, for the searches over the planner's grid;
 * a cell may be pushed more than once, and a search skips the stale entries it pops. Its arrays
 * are kept from one search to the next.
 */
final class CellHeap {
    private int[] items;
    private float[] keys;
    private int size;

    CellHeap(int capacity) {
        items = new int[Math.max(16, capacity / 8)];
        keys = new float[items.length];
    }

    void clear() {
        size = 0;
    }

    boolean isEmpty() {
        return size == 0;
    }

    void push(int item, double key) {
        if (size == items.length) {
            items = Arrays.copyOf(items, size * 2);
            keys = Arrays.copyOf(keys, size * 2);
        }
        int i = size++;
        while (i > 0) {
            int up = (i - 1) >>> 1;
            if (keys[up] <= key) {
                break;
            }
            items[i] = items[up];
            keys[i] = keys[up];
            i = up;
        }
        items[i] = item;
        keys[i] = (float) key;
    }

    int pop() {
        int top = items[0];
        int item = items[--size];
        float key = keys[size];
        int i = 0;
        while (true) {
            int child = 2 * i + 1;
            if (child >= size) {
                break;
            }
            if (child + 1 < size && keys[child + 1] < keys[child]) {
                child++;
            }
            if (keys[child] >= key) {
                break;
            }
            items[i] = items[child];
            keys[i] = keys[child];
            i = child;
        }
        items[i] = item;
        keys[i] = key;
        return top;
    }
}
