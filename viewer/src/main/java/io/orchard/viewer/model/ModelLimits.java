package io.orchard.viewer.model;

/**
 * Upper bounds on an agent model, checked while it is parsed so that a hostile model is refused
 * before it can exhaust memory or time. The defaults suit the articulated agents of the paper (a
 * few hundred nodes, a few thousand vertices) with a wide margin; a viewer that shows many agents
 * may lower them.
 *
 * @param maxInputBytes   largest accepted file, in bytes
 * @param maxNodes        most nodes, counting every node a {@code USE} repeats (so a chain of
 *                        {@code USE}s cannot multiply a small file into a huge scene)
 * @param maxDepth        deepest nesting of nodes (and of JSON in glTF); at most
 *                        {@value #DEPTH_CEILING}, because parsing nests calls as deep
 * @param maxArrayValues  most numbers in all array fields together: coordinates, indices, colours,
 *                        normals, texture coordinates, key frames; for glTF, accessor components
 * @param maxTextureSize  widest or tallest embedded texture image, in pixels
 */
public record ModelLimits(int maxInputBytes, int maxNodes, int maxDepth, int maxArrayValues,
                          int maxTextureSize) {

    /** 4 MiB, 20,000 nodes, depth 64, 1,000,000 array values, 2048-pixel textures. */
    public static final ModelLimits DEFAULTS =
            new ModelLimits(4 * 1024 * 1024, 20_000, 64, 1_000_000, 2048);

    /** The deepest nesting any limits may allow; deeper would risk the thread's stack. */
    public static final int DEPTH_CEILING = 256;

    /** Checks the components; a bad value is refused with an exception that names it. */
    public ModelLimits {
        requirePositive("maxInputBytes", maxInputBytes);
        requirePositive("maxNodes", maxNodes);
        requirePositive("maxDepth", maxDepth);
        if (maxDepth > DEPTH_CEILING) {
            throw new IllegalArgumentException("maxDepth must be at most " + DEPTH_CEILING
                    + ": " + maxDepth);
        }
        requirePositive("maxArrayValues", maxArrayValues);
        requirePositive("maxTextureSize", maxTextureSize);
    }

    /** These limits with another input size. */
    public ModelLimits withMaxInputBytes(int value) {
        return new ModelLimits(value, maxNodes, maxDepth, maxArrayValues, maxTextureSize);
    }

    /** These limits with another node count. */
    public ModelLimits withMaxNodes(int value) {
        return new ModelLimits(maxInputBytes, value, maxDepth, maxArrayValues, maxTextureSize);
    }

    /** These limits with another nesting depth. */
    public ModelLimits withMaxDepth(int value) {
        return new ModelLimits(maxInputBytes, maxNodes, value, maxArrayValues, maxTextureSize);
    }

    /** These limits with another number of array values. */
    public ModelLimits withMaxArrayValues(int value) {
        return new ModelLimits(maxInputBytes, maxNodes, maxDepth, value, maxTextureSize);
    }

    /** These limits with another texture size. */
    public ModelLimits withMaxTextureSize(int value) {
        return new ModelLimits(maxInputBytes, maxNodes, maxDepth, maxArrayValues, value);
    }

    private static void requirePositive(String name, int value) {
        if (value <= 0) {
            throw new IllegalArgumentException(name + " must be positive: " + value);
        }
    }
}
