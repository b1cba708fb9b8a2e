package io.orchard.viewer.model.event;

import com.jme3.math.Quaternion;
import io.orchard.viewer.model.ModelException;
import io.orchard.viewer.model.Rotations;
import io.orchard.viewer.model.SceneNode;

/**
 * A running Position-, Orientation- or ScalarInterpolator: on {@code set_fraction} it finds the
 * two keys around the fraction and sends the value between their key values as
 * {@code value_changed}: linear for positions and scalars, spherical (shortest path) for
 * rotations. Fractions outside the keys give the first or last key value.
 */
public final class LiveInterpolator implements LiveNode {

    /** The three interpolator types, by how many numbers one key value has. */
    public enum Kind {
        /** A PositionInterpolator: three numbers a key value. */
        POSITION(3),
        /** An OrientationInterpolator: an axis-angle rotation, four numbers a key value. */
        ORIENTATION(4),
        /** A ScalarInterpolator: one number a key value. */
        SCALAR(1);

        final int components;

        Kind(int components) {
            this.components = components;
        }

        static Kind of(String typeName) {
            return switch (typeName) {
                case "PositionInterpolator" -> POSITION;
                case "OrientationInterpolator" -> ORIENTATION;
                case "ScalarInterpolator" -> SCALAR;
                default -> throw new IllegalArgumentException(typeName);
            };
        }
    }

    private final String name;
    private final Kind kind;
    private float[] key;
    private float[] keyValue;

    /**
     * The interpolator a Position-, Orientation- or ScalarInterpolator node describes.
     *
     * @throws ModelException if its keys decrease or do not match its key values in number
     */
    public static LiveInterpolator of(SceneNode node) throws ModelException {
        Kind kind = Kind.of(node.typeName());
        float[] key = node.floats("key");
        float[] keyValue = node.floats("keyValue");
        if (keyValue.length != key.length * kind.components) {
            throw new ModelException(ModelException.Kind.BAD_VALUE, node.location() + ": "
                    + node.label() + " has " + key.length + " keys but "
                    + keyValue.length / kind.components + " key values; they must match");
        }
        for (int i = 1; i < key.length; i++) {
            if (key[i] < key[i - 1]) {
                throw new ModelException(ModelException.Kind.BAD_VALUE, node.location() + ": "
                        + node.label() + " field key must not decrease, but " + key[i]
                        + " follows " + key[i - 1]);
            }
        }
        return new LiveInterpolator(node.defName().orElse(node.label()), kind, key, keyValue);
    }

    private LiveInterpolator(String name, Kind kind, float[] key, float[] keyValue) {
        this.name = name;
        this.kind = kind;
        this.key = key.clone();
        this.keyValue = keyValue.clone();
    }

    @Override
    public String toString() {
        return "Interpolator '" + name + "'";
    }

    /** The interpolator's type. */
    public Kind kind() {
        return kind;
    }

    /** Replaces the keys, as the paper's viewer did through the EAI before each move. */
    public void setKeys(float[] newKey, float[] newKeyValue) {
        this.key = newKey.clone();
        this.keyValue = newKeyValue.clone();
    }

    @Override
    public void receive(String field, Object value, EventGraph.Cascade cascade) {
        switch (field) {
            case "set_fraction" -> {
                Object result = valueAt(((Double) value).floatValue());
                if (result != null) {
                    cascade.emit(this, "value_changed", result);
                }
            }
            case "key" -> {
                key = ((float[]) value).clone();
                cascade.emit(this, "key", value);
            }
            case "keyValue" -> {
                keyValue = ((float[]) value).clone();
                cascade.emit(this, "keyValue", value);
            }
            default -> { }
        }
    }

    /**
     * The interpolated value at {@code fraction}: a {@code float[3]}, an axis-angle
     * {@code float[4]} or a {@code Double}; null if there are no keys.
     */
    Object valueAt(float fraction) {
        int n = Math.min(key.length, keyValue.length / kind.components);
        if (n == 0) {
            return null;
        }
        int i;
        float t;
        if (fraction <= key[0]) {
            i = 0;
            t = 0;
        } else if (fraction >= key[n - 1]) {
            i = n - 1;
            t = 0;
        } else {
            i = 0;
            while (i < n - 2 && fraction >= key[i + 1]) {
                i++;
            }
            float span = key[i + 1] - key[i];
            t = span > 0 ? (fraction - key[i]) / span : 0;
        }
        int j = Math.min(i + 1, n - 1);
        return switch (kind) {
            case SCALAR -> (double) lerp(keyValue[i], keyValue[j], t);
            case POSITION -> new float[] {
                lerp(keyValue[3 * i], keyValue[3 * j], t),
                lerp(keyValue[3 * i + 1], keyValue[3 * j + 1], t),
                lerp(keyValue[3 * i + 2], keyValue[3 * j + 2], t)};
            case ORIENTATION -> {
                Quaternion a = Rotations.fromAxisAngle(keyValue, 4 * i);
                Quaternion b = Rotations.fromAxisAngle(keyValue, 4 * j);
                yield Rotations.toAxisAngle(t == 0 ? a : Rotations.slerp(a, b, t));
            }
        };
    }

    private static float lerp(float a, float b, float t) {
        return a + (b - a) * t;
    }
}
