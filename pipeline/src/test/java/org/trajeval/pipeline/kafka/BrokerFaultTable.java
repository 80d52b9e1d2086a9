package org.trajeval.pipeline.kafka;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Properties;
import java.util.Set;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The reliability script (README, "Reliability"): issue 19's fault table re-run. A real broker
 * in its own JVM ({@link BrokerProcess}), the service as the launcher runs it
 * ({@link ServiceProcess}), {@code RUNS} run events sent at a steady pace, the broker killed with
 * SIGKILL and restarted on the same ports and folder. One line per fault: runs, report files,
 * runs with a committed report event, runs with more than one, time from the broker serving
 * again to the service's next commit, whether the service stayed up, its exit code on SIGTERM.
 * {@code gradle :pipeline:reliability [-Pargs="RUNS [FAULT...]"]}; under nice, ~15 min.
 */
public final class BrokerFaultTable {
    private static final Pattern COMMIT_AGE = Pattern.compile(
            "(?m)^trajeval_pipeline_last_commit_age_seconds(?:\\{[^}]*\\})? (\\S+)$");

    private final Path dir;
    private final int runs;

    private BrokerFaultTable(Path dir, int runs) {
        this.dir = dir;
        this.runs = runs;
    }

    /** Runs the faults named (all by default) and prints the table. */
    public static void main(String[] args) throws Exception {
        int runs = args.length > 0 ? Integer.parseInt(args[0]) : 300;
        List<String> faults = args.length > 1 ? List.of(args).subList(1, args.length)
                : List.of("outage-fixed-id", "outage-default-id", "outage-service-killed", "outage-beyond-timeout",
                        "three-outages", "service-first", "no-broker", "state-loss");
        Path dir = Files.createTempDirectory("trajeval-reliability-");
        BrokerFaultTable t = new BrokerFaultTable(dir, runs);
        System.out.println("| fault | runs | report files | runs with an event | runs with >1 event | resume after broker back (s) | service up throughout | SIGTERM exit |");
        System.out.println("|---|---|---|---|---|---|---|---|");
        for (String f : faults) {
            System.out.println(t.run(f));
            System.out.flush();
        }
        System.out.println("(logs in " + dir + ")");
    }

    private String run(String fault) throws Exception {
        Path d = dir.resolve(fault);
        Files.createDirectories(d);
        if (fault.equals("no-broker")) {
            return noBroker(d);
        }
        List<String> args = new ArrayList<>(List.of("--set", "kafka.group_id=reliability", "--set",
                "kafka.unhealthy_after_s=5"));
        switch (fault) {
            case "outage-fixed-id" -> args.addAll(List.of("--set", "kafka.instance_id=fixed"));
            case "outage-beyond-timeout" -> args.addAll(List.of("--set", "kafka.transaction_timeout_ms=10000"));
            default -> {
            }
        }
        BrokerProcess broker = null;
        ServiceProcess svc = null;
        List<Double> resumes = new ArrayList<>();
        boolean upThroughout = true;
        boolean sawDown = false;
        try {
            if (fault.equals("service-first")) {
                // the service starts 30 s before the broker exists
                broker = BrokerProcess.prepare(d.resolve("broker-data"), d.resolve("broker.log"), null);
                svc = ServiceProcess.start(d.resolve("svc"), broker.bootstrapServers(), d.resolve("service.log"), args);
                Thread.sleep(30_000);
                upThroughout &= svc.isAlive();
                broker.restart();
            } else {
                broker = BrokerProcess.start(d.resolve("broker-data"), d.resolve("broker.log"), null);
                BrokerMain.createTopics(broker.bootstrapServers(), RunEvents.TOPICS);
                svc = ServiceProcess.start(d.resolve("svc"), broker.bootstrapServers(), d.resolve("service.log"), args);
            }
            Properties client = RunEvents.plain(broker.bootstrapServers());
            ExecutorService sender = Executors.newSingleThreadExecutor();
            Future<?> sending = sender.submit(() -> {
                RunEvents.send(client, 0, runs, Duration.ofMillis(50));
                return null;
            });
            Path reports = d.resolve("svc").resolve("reports");
            int outages = switch (fault) {
                case "three-outages" -> 3;
                case "service-first" -> 0;
                default -> 1;
            };
            for (int o = 0; o < outages; o++) {
                awaitFiles(reports, runs * (o + 1) / (outages + 2));
                broker.kill();
                if (fault.equals("state-loss")) {
                    broker.wipe();
                }
                long back = System.nanoTime() + Duration.ofSeconds(fault.equals("three-outages") ? 24 : 20).toNanos();
                while (System.nanoTime() < back) {
                    sawDown |= svc.health().startsWith("503");
                    Thread.sleep(500);
                }
                if (fault.equals("outage-service-killed")) {
                    svc.kill(); // dies with its transaction open; restarted below with the same default id
                } else {
                    upThroughout &= svc.isAlive();
                }
                broker.restart();
                Instant ready = Instant.now();
                if (fault.equals("outage-service-killed")) {
                    svc = ServiceProcess.start(d.resolve("svc"), broker.bootstrapServers(), d.resolve("service.log"), args);
                }
                resumes.add(resumeSeconds(svc, ready));
            }
            sending.get();
            sender.shutdown();
            if (fault.equals("state-loss")) {
                // as the operator of issue 19 did: every event sent again, into the re-created topic
                RunEvents.send(client, 0, runs, Duration.ZERO);
            }
            Set<String> all = RunEvents.ids(0, runs);
            Map<String, Integer> events = RunEvents.awaitEvents(client, all, Duration.ofSeconds(300));
            upThroughout &= svc.isAlive();
            int exit = svc.terminate();
            Set<String> files = RunEvents.reportFiles(reports);
            long withEvent = all.stream().filter(events::containsKey).count();
            long repeated = events.values().stream().filter(n -> n > 1).count();
            return String.format(Locale.ROOT, "| %s | %d | %d | %d | %d | %s | %s%s | %d |", fault, runs,
                    files.size(), withEvent, repeated, resumes.isEmpty() ? "-" : resumes.toString(),
                    upThroughout ? "yes" : "no", sawDown ? " (503 while down)" : "", exit);
        } finally {
            if (svc != null) {
                svc.close();
            }
            if (broker != null) {
                broker.close();
            }
        }
    }

    /** No broker at all: the service waits, then exits 5 after --startup-timeout with one line. */
    private String noBroker(Path d) throws Exception {
        ServiceProcess svc = ServiceProcess.start(d.resolve("svc"), "127.0.0.1:" + EmbeddedBroker.freePort(),
                d.resolve("service.log"), List.of("--startup-timeout", "30"));
        boolean ended = svc.process().waitFor(120, java.util.concurrent.TimeUnit.SECONDS);
        String log = svc.log();
        long lines = log.lines().count();
        String last = log.lines().reduce((a, b) -> b).orElse("");
        return String.format(Locale.ROOT, "| no-broker (--startup-timeout 30) | - | - | - | - | - | exit %s, %d log lines, "
                + "stack trace: %s; last line: `%s` | - |", ended ? String.valueOf(svc.process().exitValue()) : "none",
                lines, log.contains("\tat ") ? "yes" : "no", last);
    }

    private void awaitFiles(Path reports, int atLeast) throws Exception {
        long deadline = System.nanoTime() + Duration.ofSeconds(300).toNanos();
        while (RunEvents.reportFiles(reports).size() < atLeast && System.nanoTime() < deadline) {
            Thread.sleep(50);
        }
    }

    /** @return seconds from {@code ready} to the service's first commit after it (from /metrics), or NaN */
    private static double resumeSeconds(ServiceProcess svc, Instant ready) throws InterruptedException {
        long deadline = System.nanoTime() + Duration.ofSeconds(180).toNanos();
        while (System.nanoTime() < deadline) {
            Matcher m = COMMIT_AGE.matcher(svc.metrics());
            if (m.find() && !m.group(1).equals("NaN")) {
                Instant commit = Instant.now().minusMillis(Math.round(Double.parseDouble(m.group(1)) * 1000));
                if (commit.isAfter(ready)) {
                    return Math.round(Duration.between(ready, commit).toMillis() / 100.0) / 10.0;
                }
            }
            Thread.sleep(100);
        }
        return Double.NaN;
    }
}
