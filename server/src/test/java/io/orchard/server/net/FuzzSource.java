package io.orchard.server.net;

import com.code_intelligence.jazzer.api.FuzzedDataProvider;
import java.util.Random;

/** Where a fuzzed client's choices come from: Jazzer's mutated bytes, or a seeded generator. */
interface FuzzSource {

    /** A number from {@code min} to {@code max}, both included. */
    int pick(int min, int max);

    /** Any double, NaN and the infinities included. */
    double anyDouble();

    /** Any long. */
    long anyLong();

    /** A string of at most {@code max} characters, any of them. */
    String text(int max);

    /** Raw bytes, at most {@code max}. */
    byte[] bytes(int max);

    /** Whether there is anything left to choose from. */
    boolean more();

    static FuzzSource of(FuzzedDataProvider data) {
        return new FuzzSource() {
            @Override
            public int pick(int min, int max) {
                return data.consumeInt(min, max);
            }

            @Override
            public double anyDouble() {
                return data.consumeDouble();
            }

            @Override
            public long anyLong() {
                return data.consumeLong();
            }

            @Override
            public String text(int max) {
                return data.consumeString(max);
            }

            @Override
            public byte[] bytes(int max) {
                return data.consumeBytes(max);
            }

            @Override
            public boolean more() {
                return data.remainingBytes() > 0;
            }
        };
    }

    static FuzzSource of(Random random, int choices) {
        return new FuzzSource() {
            private int left = choices;

            @Override
            public int pick(int min, int max) {
                left--;
                return min + (int) Math.floorMod(random.nextLong(), (long) max - min + 1);
            }

            @Override
            public double anyDouble() {
                left--;
                return switch (random.nextInt(8)) {
                    case 0 -> Double.NaN;
                    case 1 -> random.nextBoolean() ? Double.POSITIVE_INFINITY : Double.NEGATIVE_INFINITY;
                    case 2 -> Double.longBitsToDouble(random.nextLong());
                    case 3 -> random.nextBoolean() ? Double.MAX_VALUE : -Double.MIN_VALUE;
                    default -> (random.nextDouble() - 0.5) * Math.pow(10, random.nextInt(6));
                };
            }

            @Override
            public long anyLong() {
                left--;
                return random.nextInt(4) == 0 ? random.nextLong() : random.nextInt(100) - 10;
            }

            @Override
            public String text(int max) {
                left--;
                int length = random.nextInt(max + 1);
                StringBuilder text = new StringBuilder(length);
                for (int i = 0; i < length; i++) {
                    text.append((char) (random.nextInt(4) == 0 ? random.nextInt(0x3000) : 32 + random.nextInt(95)));
                }
                return text.toString();
            }

            @Override
            public byte[] bytes(int max) {
                left--;
                byte[] bytes = new byte[random.nextInt(max + 1)];
                random.nextBytes(bytes);
                return bytes;
            }

            @Override
            public boolean more() {
                return left > 0;
            }
        };
    }
}
