package io.orchard.viewer.model;

import static io.orchard.viewer.model.FieldDef.Access.EVENT_IN;
import static io.orchard.viewer.model.FieldDef.Access.EVENT_OUT;
import static io.orchard.viewer.model.FieldDef.Access.EXPOSED;
import static io.orchard.viewer.model.FieldDef.Access.FIELD;
import static io.orchard.viewer.model.FieldType.MFCOLOR;
import static io.orchard.viewer.model.FieldType.MFFLOAT;
import static io.orchard.viewer.model.FieldType.MFINT32;
import static io.orchard.viewer.model.FieldType.MFNODE;
import static io.orchard.viewer.model.FieldType.MFROTATION;
import static io.orchard.viewer.model.FieldType.MFSTRING;
import static io.orchard.viewer.model.FieldType.MFVEC2F;
import static io.orchard.viewer.model.FieldType.MFVEC3F;
import static io.orchard.viewer.model.FieldType.SFBOOL;
import static io.orchard.viewer.model.FieldType.SFCOLOR;
import static io.orchard.viewer.model.FieldType.SFFLOAT;
import static io.orchard.viewer.model.FieldType.SFINT32;
import static io.orchard.viewer.model.FieldType.SFNODE;
import static io.orchard.viewer.model.FieldType.SFROTATION;
import static io.orchard.viewer.model.FieldType.SFSTRING;
import static io.orchard.viewer.model.FieldType.SFTIME;
import static io.orchard.viewer.model.FieldType.SFVEC3F;

import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

/**
 * The node types this loader builds, with their VRML97 fields and defaults. A node of any other
 * type is still parsed (so its DEF names and nested nodes are known) but not built.
 */
public final class NodeSchema {

    private static final Map<String, NodeType> TYPES = new HashMap<>();

    static {
        for (String group : List.of("Group", "Transform", "Collision", "Anchor", "Billboard")) {
            Map<String, FieldDef> f = grouping();
            switch (group) {
                case "Transform" -> {
                    add(f, "center", SFVEC3F, EXPOSED, vec(0, 0, 0));
                    add(f, "rotation", SFROTATION, EXPOSED, vec(0, 0, 1, 0));
                    add(f, "scale", SFVEC3F, EXPOSED, vec(1, 1, 1));
                    add(f, "scaleOrientation", SFROTATION, EXPOSED, vec(0, 0, 1, 0));
                    add(f, "translation", SFVEC3F, EXPOSED, vec(0, 0, 0));
                }
                case "Collision" -> {
                    add(f, "collide", SFBOOL, EXPOSED, true);
                    add(f, "enabled", SFBOOL, EXPOSED, true);
                    nodeField(f, "proxy", SFNODE, FIELD, NodeKind.CHILD);
                    add(f, "collideTime", SFTIME, EVENT_OUT, 0.0);
                }
                case "Anchor" -> {
                    add(f, "description", SFSTRING, EXPOSED, "");
                    add(f, "parameter", MFSTRING, EXPOSED, List.of());
                    add(f, "url", MFSTRING, EXPOSED, List.of());
                }
                case "Billboard" -> add(f, "axisOfRotation", SFVEC3F, EXPOSED, vec(0, 1, 0));
                default -> { }
            }
            type(group, NodeKind.CHILD, "children", f);
        }
        Map<String, FieldDef> sw = grouping();
        nodeField(sw, "choice", MFNODE, EXPOSED, NodeKind.CHILD);
        add(sw, "whichChoice", SFINT32, EXPOSED, -1);
        type("Switch", NodeKind.CHILD, "children", sw);

        Map<String, FieldDef> lod = grouping();
        nodeField(lod, "level", MFNODE, EXPOSED, NodeKind.CHILD);
        add(lod, "center", SFVEC3F, FIELD, vec(0, 0, 0));
        add(lod, "range", MFFLOAT, FIELD, new float[0]);
        type("LOD", NodeKind.CHILD, "children", lod);

        Map<String, FieldDef> shape = common();
        nodeField(shape, "appearance", SFNODE, EXPOSED, NodeKind.APPEARANCE);
        nodeField(shape, "geometry", SFNODE, EXPOSED, NodeKind.GEOMETRY);
        type("Shape", NodeKind.CHILD, "children", shape);

        Map<String, FieldDef> appearance = common();
        nodeField(appearance, "material", SFNODE, EXPOSED, NodeKind.MATERIAL);
        nodeField(appearance, "texture", SFNODE, EXPOSED, NodeKind.TEXTURE);
        nodeField(appearance, "textureTransform", SFNODE, EXPOSED, NodeKind.ANY);
        type("Appearance", NodeKind.APPEARANCE, "appearance", appearance);

        Map<String, FieldDef> material = common();
        add(material, "ambientIntensity", SFFLOAT, EXPOSED, 0.2);
        add(material, "diffuseColor", SFCOLOR, EXPOSED, vec(0.8f, 0.8f, 0.8f));
        add(material, "emissiveColor", SFCOLOR, EXPOSED, vec(0, 0, 0));
        add(material, "shininess", SFFLOAT, EXPOSED, 0.2);
        add(material, "specularColor", SFCOLOR, EXPOSED, vec(0, 0, 0));
        add(material, "transparency", SFFLOAT, EXPOSED, 0.0);
        type("Material", NodeKind.MATERIAL, "material", material);

        Map<String, FieldDef> texture = common();
        add(texture, "url", MFSTRING, EXPOSED, List.of());
        add(texture, "repeatS", SFBOOL, FIELD, true);
        add(texture, "repeatT", SFBOOL, FIELD, true);
        type("ImageTexture", NodeKind.TEXTURE, "texture", texture);

        Map<String, FieldDef> box = common();
        add(box, "size", SFVEC3F, FIELD, vec(2, 2, 2));
        type("Box", NodeKind.GEOMETRY, "geometry", box);

        Map<String, FieldDef> sphere = common();
        add(sphere, "radius", SFFLOAT, FIELD, 1.0);
        type("Sphere", NodeKind.GEOMETRY, "geometry", sphere);

        Map<String, FieldDef> cylinder = common();
        add(cylinder, "bottom", SFBOOL, FIELD, true);
        add(cylinder, "height", SFFLOAT, FIELD, 2.0);
        add(cylinder, "radius", SFFLOAT, FIELD, 1.0);
        add(cylinder, "side", SFBOOL, FIELD, true);
        add(cylinder, "top", SFBOOL, FIELD, true);
        type("Cylinder", NodeKind.GEOMETRY, "geometry", cylinder);

        Map<String, FieldDef> cone = common();
        add(cone, "bottomRadius", SFFLOAT, FIELD, 1.0);
        add(cone, "height", SFFLOAT, FIELD, 2.0);
        add(cone, "side", SFBOOL, FIELD, true);
        add(cone, "bottom", SFBOOL, FIELD, true);
        type("Cone", NodeKind.GEOMETRY, "geometry", cone);

        Map<String, FieldDef> faces = common();
        nodeField(faces, "color", SFNODE, EXPOSED, NodeKind.COLOR);
        nodeField(faces, "coord", SFNODE, EXPOSED, NodeKind.COORDINATE);
        nodeField(faces, "normal", SFNODE, EXPOSED, NodeKind.NORMAL);
        nodeField(faces, "texCoord", SFNODE, EXPOSED, NodeKind.TEXTURE_COORDINATE);
        add(faces, "ccw", SFBOOL, FIELD, true);
        add(faces, "colorIndex", MFINT32, FIELD, new int[0]);
        add(faces, "colorPerVertex", SFBOOL, FIELD, true);
        add(faces, "convex", SFBOOL, FIELD, true);
        add(faces, "coordIndex", MFINT32, FIELD, new int[0]);
        add(faces, "creaseAngle", SFFLOAT, FIELD, 0.0);
        add(faces, "normalIndex", MFINT32, FIELD, new int[0]);
        add(faces, "normalPerVertex", SFBOOL, FIELD, true);
        add(faces, "solid", SFBOOL, FIELD, true);
        add(faces, "texCoordIndex", MFINT32, FIELD, new int[0]);
        for (String index : List.of("colorIndex", "coordIndex", "normalIndex", "texCoordIndex")) {
            add(faces, "set_" + index, MFINT32, EVENT_IN, new int[0]);
        }
        type("IndexedFaceSet", NodeKind.GEOMETRY, "geometry", faces);

        Map<String, FieldDef> lines = common();
        nodeField(lines, "color", SFNODE, EXPOSED, NodeKind.COLOR);
        nodeField(lines, "coord", SFNODE, EXPOSED, NodeKind.COORDINATE);
        add(lines, "colorIndex", MFINT32, FIELD, new int[0]);
        add(lines, "colorPerVertex", SFBOOL, FIELD, true);
        add(lines, "coordIndex", MFINT32, FIELD, new int[0]);
        add(lines, "set_colorIndex", MFINT32, EVENT_IN, new int[0]);
        add(lines, "set_coordIndex", MFINT32, EVENT_IN, new int[0]);
        type("IndexedLineSet", NodeKind.GEOMETRY, "geometry", lines);

        type("Coordinate", NodeKind.COORDINATE, "coord",
                with(common(), "point", MFVEC3F));
        type("Normal", NodeKind.NORMAL, "normal", with(common(), "vector", MFVEC3F));
        type("Color", NodeKind.COLOR, "color", with(common(), "color", MFCOLOR));
        type("TextureCoordinate", NodeKind.TEXTURE_COORDINATE, "texCoord",
                with(common(), "point", MFVEC2F));

        Map<String, FieldDef> sensor = common();
        add(sensor, "cycleInterval", SFTIME, EXPOSED, 1.0);
        add(sensor, "enabled", SFBOOL, EXPOSED, true);
        add(sensor, "loop", SFBOOL, EXPOSED, false);
        add(sensor, "startTime", SFTIME, EXPOSED, 0.0);
        add(sensor, "stopTime", SFTIME, EXPOSED, 0.0);
        add(sensor, "cycleTime", SFTIME, EVENT_OUT, 0.0);
        add(sensor, "fraction_changed", SFFLOAT, EVENT_OUT, 0.0);
        add(sensor, "isActive", SFBOOL, EVENT_OUT, false);
        add(sensor, "time", SFTIME, EVENT_OUT, 0.0);
        type("TimeSensor", NodeKind.CHILD, "children", sensor);

        type("PositionInterpolator", NodeKind.CHILD, "children", interpolator(MFVEC3F,
                FieldType.SFVEC3F));
        type("OrientationInterpolator", NodeKind.CHILD, "children", interpolator(MFROTATION,
                SFROTATION));
        type("ScalarInterpolator", NodeKind.CHILD, "children", interpolator(MFFLOAT, SFFLOAT));
    }

    private NodeSchema() {
    }

    /** The type of that name, or empty for node types this loader does not build. */
    public static Optional<NodeType> find(String typeName) {
        return Optional.ofNullable(TYPES.get(typeName));
    }

    /** The field a child element of an unknown type fills in the XML encoding. */
    public static String defaultContainerField(String typeName) {
        NodeType type = TYPES.get(typeName);
        if (type != null) {
            return type.containerField();
        }
        return typeName.startsWith("Metadata") ? "metadata" : "children";
    }

    private static Map<String, FieldDef> common() {
        Map<String, FieldDef> fields = new LinkedHashMap<>();
        nodeField(fields, "metadata", SFNODE, EXPOSED, NodeKind.ANY);
        return fields;
    }

    private static Map<String, FieldDef> grouping() {
        Map<String, FieldDef> fields = common();
        nodeField(fields, "children", MFNODE, EXPOSED, NodeKind.CHILD);
        nodeField(fields, "addChildren", MFNODE, EVENT_IN, NodeKind.CHILD);
        nodeField(fields, "removeChildren", MFNODE, EVENT_IN, NodeKind.CHILD);
        add(fields, "bboxCenter", SFVEC3F, FIELD, vec(0, 0, 0));
        add(fields, "bboxSize", SFVEC3F, FIELD, vec(-1, -1, -1));
        return fields;
    }

    private static Map<String, FieldDef> interpolator(FieldType keyValues, FieldType value) {
        Map<String, FieldDef> fields = common();
        add(fields, "set_fraction", SFFLOAT, EVENT_IN, 0.0);
        add(fields, "key", MFFLOAT, EXPOSED, new float[0]);
        add(fields, "keyValue", keyValues, EXPOSED, new float[0]);
        add(fields, "value_changed", value, EVENT_OUT, null);
        return fields;
    }

    private static Map<String, FieldDef> with(Map<String, FieldDef> fields, String name,
                                              FieldType type) {
        add(fields, name, type, EXPOSED, new float[0]);
        return fields;
    }

    private static void add(Map<String, FieldDef> fields, String name, FieldType type,
                            FieldDef.Access access, Object defaultValue) {
        fields.put(name, new FieldDef(name, type, access, defaultValue, null));
    }

    private static void nodeField(Map<String, FieldDef> fields, String name, FieldType type,
                                  FieldDef.Access access, NodeKind accepts) {
        Object empty = type == MFNODE ? List.of() : null;
        fields.put(name, new FieldDef(name, type, access, empty, accepts));
    }

    private static void type(String name, NodeKind kind, String container,
                             Map<String, FieldDef> fields) {
        TYPES.put(name, new NodeType(name, kind, container, fields));
    }

    private static float[] vec(float... values) {
        return values;
    }
}
