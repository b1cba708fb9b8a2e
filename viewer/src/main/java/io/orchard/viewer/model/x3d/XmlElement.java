package io.orchard.viewer.model.x3d;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * One element of an X3D document as read: its name, its attributes without a namespace prefix in
 * document order, where it starts, and its child elements (text between elements is not kept;
 * X3D puts no data there). PROTO expansion copies and edits these before the scene is built.
 */
final class XmlElement {

    private final String name;
    private final Map<String, String> attributes;
    private final String location;
    private final List<XmlElement> children = new ArrayList<>();

    XmlElement(String name, Map<String, String> attributes, String location) {
        this.name = name;
        this.attributes = new LinkedHashMap<>(attributes);
        this.location = location;
    }

    String name() {
        return name;
    }

    String location() {
        return location;
    }

    /** The attribute's value, or null. */
    String attribute(String key) {
        return attributes.get(key);
    }

    Map<String, String> attributes() {
        return attributes;
    }

    void setAttribute(String key, String value) {
        if (value == null) {
            attributes.remove(key);
        } else {
            attributes.put(key, value);
        }
    }

    List<XmlElement> children() {
        return children;
    }

    /** A copy of this element and everything below it, which may be edited on its own. */
    XmlElement copy(int[] budget) {
        budget[0]--;
        XmlElement copy = new XmlElement(name, attributes, location);
        for (XmlElement child : children) {
            copy.children.add(child.copy(budget));
        }
        return copy;
    }
}
