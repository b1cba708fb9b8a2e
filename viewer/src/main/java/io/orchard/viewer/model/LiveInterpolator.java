package io.orchard.viewer.model;

import com.jme3.math.Quaternion;

/**
 * A running Position-, Orientation- or ScalarInterpolator: on {@code set_fraction} it finds the
 * two keys around the fraction and sends the value between their key values as
 * {@code value_changed}: linear for positions and scalars, spherical (shortest path) for
 * rotations. Fractions outside the keys give the first or last key value.
 */
final class LiveInterpolator implements LiveNode {

    /** The three interpolator types, by how many numbers one key value has. */
    enum Kind {
        POSITION(3), ORIENTATION(4), SCALAR(1);

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

    LiveInterpolator(String name, Kind kind, float[] key, float[] keyValue) {
        this.name = name;
        this.kind = kind;
        this.key = key.clone();
        this.keyValue = keyValue.clone();
    }

    @Override
    public String toString() {
        return "Interpolator '" + name + "'";
    }

    Kind kind() {
        return kind;
    }

    /** Replaces the keys, as the paper's viewer did through the EAI before each move. */
    void setKeys(float[] newKey, float[] newKeyValue) {
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
