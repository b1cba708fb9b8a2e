package io.orchard.server.bench;

/**
 * {@link TickBenchmark}'s tick timed on the thread's CPU clock ({@link CpuRounds}), for a machine
 * too busy for JMH's wall clock.
 *
 * <pre>
 * java -cp ... io.orchard.server.bench.TickCpuTime [agents 1000] [warm-up ticks 600] [rounds 10] [ticks a round 100]
 * </pre>
 */
public final class TickCpuTime {

    private TickCpuTime() {}

    /** Runs the rounds and prints them. */
    public static void main(String[] args) {
        TickBenchmark bench = new TickBenchmark();
        bench.agents = args.length > 0 ? Integer.parseInt(args[0]) : 1000;
        bench.setUp();
        CpuRounds.run("tick of " + bench.agents + " agents", bench::tick, args.length > 1 ? Integer.parseInt(args[1]) : 600,
                args.length > 2 ? Integer.parseInt(args[2]) : 10, args.length > 3 ? Integer.parseInt(args[3]) : 100);
    }
}
