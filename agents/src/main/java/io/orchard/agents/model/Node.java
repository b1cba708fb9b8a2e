package io.orchard.agents.model;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * A node of an X3D or VRML97 scene as {@link ModelInfo} reads it, whatever the encoding: its type,
 * its DEF name, its fields as text, and its child nodes by field. A {@code USE} is the same object in
 * two places.
 */
final class Node {

    final String type;
    final String def;
    final Map<String, String> fields = new LinkedHashMap<>();
    final Map<String, List<Node>> children = new LinkedHashMap<>();

    Node(String type, String def) {
        this.type = type;
        this.def = def;
    }

    void add(String field, Node child) {
        children.computeIfAbsent(field, f -> new ArrayList<>()).add(child);
    }

    /** The numbers of a field, or {@code defaults} when it is not set or does not read as numbers. */
    double[] numbers(String field, double... defaults) {
        String text = fields.get(field);
        if (text == null) {
            return defaults;
        }
        String[] parts = text.replace(',', ' ').trim().split("\\s+");
        double[] values = new double[parts.length];
        try {
            for (int i = 0; i < parts.length; i++) {
                values[i] = Double.parseDouble(parts[i]);
            }
        } catch (NumberFormatException e) {
            return defaults;
        }
        return parts.length == 1 && parts[0].isEmpty() ? defaults : values;
    }
}
