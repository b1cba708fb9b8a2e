package io.orchard.server.bench;

import io.netty.buffer.ByteBuf;
import io.netty.buffer.ByteBufUtil;
import io.netty.channel.ChannelHandlerContext;
import io.netty.channel.SimpleChannelInboundHandler;
import java.nio.charset.StandardCharsets;
import java.util.SplittableRandom;
import java.util.concurrent.atomic.AtomicLongArray;
import java.util.concurrent.atomic.LongAdder;

/**
 * The clients of the load generator: agents that perceive and move every tick, and viewers that
 * only read. They read just the few fields they need by scanning the line (the server writes
 * {@code type} first), so that thousands of them fit beside the server on two cores.
 */
final class LoadClients {

    /** What every client counts, shared by all of them. */
    static final class Stats {
        final LongAdder linesSent = new LongAdder();
        final LongAdder agentLinesReceived = new LongAdder();
        final LongAdder viewerLinesReceived = new LongAdder();
        final LongAdder viewerBytesReceived = new LongAdder();
        final LongAdder agentBytesReceived = new LongAdder();
        final LongAdder ticksStarted = new LongAdder();
        final LongAdder perceptions = new LongAdder();
        final LongAdder errors = new LongAdder();
        final LongAdder closed = new LongAdder();
        final LongAdder registered = new LongAdder();
        final LongAdder welcomed = new LongAdder();
        /** Perception requests sent again because no perception came for a second. */
        final LongAdder retries = new LongAdder();
        /** From sending a perception request to receiving the perception it asked for. */
        final Latencies requestToPerception = new Latencies();
        /** From the start of the tick a perception was computed in to its arrival at the client. */
        final Latencies perceptionAge = new Latencies();
        /** System.nanoTime when each tick began, by tick number modulo the ring's size. */
        final AtomicLongArray tickStarts = new AtomicLongArray(1 << 12);
        volatile boolean measuring;

        void reset() {
            linesSent.reset();
            agentLinesReceived.reset();
            viewerLinesReceived.reset();
            viewerBytesReceived.reset();
            agentBytesReceived.reset();
            perceptions.reset();
            errors.reset();
            retries.reset();
            requestToPerception.reset();
            perceptionAge.reset();
        }

        void tickStarted(long tick, long nanos) {
            ticksStarted.increment();
            tickStarts.set((int) (tick & (tickStarts.length() - 1)), nanos);
        }
    }

    private static final byte[] POSITION = "\"position\":{\"x\":".getBytes(StandardCharsets.US_ASCII);
    private static final byte[] LEAN_POSITION = "\"position\":[".getBytes(StandardCharsets.US_ASCII);
    private static final byte[] Z = "\"z\":".getBytes(StandardCharsets.US_ASCII);
    private static final byte[] TICK = "\"tick\":".getBytes(StandardCharsets.US_ASCII);
    private static final String BODY = "{\"radius\":0.5,\"height\":1.5,\"maxSpeed\":10,\"gripper\":{\"part\":\"hands\","
            + "\"reach\":0.6,\"minHeight\":0,\"maxHeight\":1.5},\"sight\":{\"range\":50,\"fieldOfView\":2.0944}}";

    private LoadClients() {}

    /**
     * An agent that asks for its perception every tick and, on each one, walks a step somewhere near.
     * A lean one reads the lean form: a perception in one line, and no answer to an accepted move.
     */
    static final class Agent extends SimpleChannelInboundHandler<ByteBuf> {

        private final String name;
        private final Stats stats;
        private final double limit;
        private final SplittableRandom random;
        private final boolean lean;
        private long seq = 1;
        private double x;
        private double z;
        private long requested;
        private boolean registered;

        Agent(String name, Stats stats, double halfSize, long seed, boolean lean) {
            this.name = name;
            this.lean = lean;
            this.stats = stats;
            this.limit = halfSize - 2;
            this.random = new SplittableRandom(seed);
        }

        @Override
        public void channelActive(ChannelHandlerContext ctx) {
            send(ctx, "{\"type\":\"Hello\",\"seq\":" + seq++ + (lean
                    ? ",\"protocolVersion\":2,\"role\":\"agent\",\"client\":\"load\",\"reads\":[\"LeanPerception\"]}\n"
                    : ",\"protocolVersion\":1,\"role\":\"agent\",\"client\":\"load\"}\n"));
            // As a real agent would: ask again when a perception is a second late (a reply that came
            // after its tick ended still counts, so this is rare).
            ctx.executor().scheduleAtFixedRate(() -> {
                if (registered && System.nanoTime() - requested > 1_000_000_000L && ctx.channel().isActive()) {
                    stats.retries.increment();
                    requested = System.nanoTime();
                    send(ctx, perceptionRequest());
                }
            }, 1, 1, java.util.concurrent.TimeUnit.SECONDS);
        }

        @Override
        protected void channelRead0(ChannelHandlerContext ctx, ByteBuf line) {
            long now = System.nanoTime();
            stats.agentLinesReceived.increment();
            stats.agentBytesReceived.add(line.readableBytes() + 1);
            String type = typeOf(line);
            switch (type) {
                case "Perception", "LeanPerception" -> {
                    long tick = number(line, TICK, 0).longValue();
                    stats.perceptions.increment();
                    if (stats.measuring) {
                        stats.requestToPerception.record(now - requested);
                        long began = stats.tickStarts.get((int) (tick & (stats.tickStarts.length() - 1)));
                        if (began != 0) {
                            stats.perceptionAge.record(now - began);
                        }
                    }
                    readPosition(line);
                    act(ctx, now);
                }
                case "Welcome" -> {
                    stats.welcomed.increment();
                    send(ctx, "{\"type\":\"Register\",\"seq\":" + seq++ + ",\"name\":\"" + name
                            + "\",\"body\":" + BODY + "}\n");
                }
                case "Registered" -> {
                    registered = true;
                    stats.registered.increment();
                    readPosition(line);
                    requested = now;
                    send(ctx, perceptionRequest());
                }
                case "Error" -> {
                    stats.errors.increment();
                    if (stats.errors.sum() <= 5) {
                        System.err.println(name + ": " + line.toString(StandardCharsets.UTF_8));
                    }
                }
                default -> { }
            }
        }

        private void act(ChannelHandlerContext ctx, long now) {
            double toX = clamp(x + random.nextDouble(-2, 2));
            double toZ = clamp(z + random.nextDouble(-2, 2));
            requested = now;
            send(ctx, "{\"type\":\"Move\",\"seq\":" + seq++ + ",\"agent\":\"" + name + "\",\"from\":{\"x\":" + x
                    + ",\"y\":0,\"z\":" + z + "},\"to\":{\"x\":" + round(toX) + ",\"y\":0,\"z\":" + round(toZ) + "}}\n"
                    + perceptionRequest());
            stats.linesSent.increment();
        }

        private String perceptionRequest() {
            return "{\"type\":\"PerceptionRequest\",\"seq\":" + seq++ + ",\"agent\":\"" + name + "\",\"every\":0}\n";
        }

        private void readPosition(ByteBuf line) {
            int lean = indexOf(line, LEAN_POSITION, 0);
            if (lean >= 0) {
                int start = line.readerIndex() + lean + LEAN_POSITION.length;
                int comma = line.indexOf(start, line.writerIndex(), (byte) ',');
                int second = line.indexOf(comma + 1, line.writerIndex(), (byte) ',');
                int end = line.indexOf(second + 1, line.writerIndex(), (byte) ']');
                x = Integer.parseInt(line.toString(start, comma - start, StandardCharsets.US_ASCII)) / 100.0;
                z = Integer.parseInt(line.toString(second + 1, end - second - 1, StandardCharsets.US_ASCII)) / 100.0;
                return;
            }
            int at = indexOf(line, POSITION, 0);
            if (at >= 0) {
                x = number(line, POSITION, at).doubleValue();
                z = number(line, Z, at).doubleValue();
            }
        }

        private double clamp(double value) {
            return Math.max(-limit, Math.min(limit, value));
        }

        private void send(ChannelHandlerContext ctx, String lines) {
            stats.linesSent.increment();
            ctx.writeAndFlush(ctx.alloc().buffer(lines.length()).writeBytes(lines.getBytes(StandardCharsets.UTF_8)));
        }

        @Override
        public void channelInactive(ChannelHandlerContext ctx) {
            stats.closed.increment();
        }

        @Override
        public void exceptionCaught(ChannelHandlerContext ctx, Throwable cause) {
            ctx.close();
        }
    }

    /** A viewer: says hello and counts what it is sent. */
    static final class Viewer extends SimpleChannelInboundHandler<ByteBuf> {

        private final Stats stats;

        Viewer(Stats stats) {
            this.stats = stats;
        }

        @Override
        public void channelActive(ChannelHandlerContext ctx) {
            stats.linesSent.increment();
            ctx.writeAndFlush(ByteBufUtil.writeUtf8(ctx.alloc(),
                    "{\"type\":\"Hello\",\"seq\":1,\"protocolVersion\":1,\"role\":\"viewer\",\"client\":\"load\"}\n"));
        }

        @Override
        protected void channelRead0(ChannelHandlerContext ctx, ByteBuf line) {
            stats.viewerLinesReceived.increment();
            stats.viewerBytesReceived.add(line.readableBytes() + 1);
        }

        @Override
        public void channelInactive(ChannelHandlerContext ctx) {
            stats.closed.increment();
        }

        @Override
        public void exceptionCaught(ChannelHandlerContext ctx, Throwable cause) {
            ctx.close();
        }
    }

    /** The message type: the server writes {@code {"type":"} first. */
    static String typeOf(ByteBuf line) {
        int start = line.readerIndex() + 9;
        int end = line.indexOf(start, line.writerIndex(), (byte) '"');
        return end < 0 ? "" : line.toString(start, end - start, StandardCharsets.US_ASCII);
    }

    /** The number that follows {@code key}, searching from {@code from} (relative to the line's start). */
    static Number number(ByteBuf line, byte[] key, int from) {
        int at = indexOf(line, key, from);
        if (at < 0) {
            return 0;
        }
        int start = line.readerIndex() + at + key.length;
        int end = start;
        while (end < line.writerIndex() && line.getByte(end) != ',' && line.getByte(end) != '}') {
            end++;
        }
        return Double.parseDouble(line.toString(start, end - start, StandardCharsets.US_ASCII));
    }

    /** Where {@code key} starts in the line at or after {@code from}, relative to the line's start; -1 if nowhere. */
    static int indexOf(ByteBuf line, byte[] key, int from) {
        int base = line.readerIndex();
        int last = line.writerIndex() - key.length;
        outer:
        for (int i = base + from; i <= last; i++) {
            for (int k = 0; k < key.length; k++) {
                if (line.getByte(i + k) != key[k]) {
                    continue outer;
                }
            }
            return i - base;
        }
        return -1;
    }

    static double round(double value) {
        return Math.round(value * 100) / 100.0;
    }
}
