package org.trajeval.pipeline;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.time.Clock;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.function.Function;
import org.trajeval.core.InputException;
import org.trajeval.core.Version;
import org.trajeval.pipeline.bundle.BundleOpener;
import org.trajeval.pipeline.dir.DirectoryLayout;
import org.trajeval.pipeline.dir.DirectoryService;
import org.trajeval.pipeline.dir.DrainSummary;
import org.trajeval.pipeline.kafka.BrokerFailure;
import org.trajeval.pipeline.kafka.KafkaClients;
import org.trajeval.pipeline.kafka.KafkaMode;
import org.trajeval.pipeline.ledger.Ledger;
import org.trajeval.pipeline.metrics.HttpEndpoint;
import org.trajeval.pipeline.metrics.PipelineMetrics;
import org.trajeval.pipeline.store.ResultsRecorder;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * {@code trajeval-pipeline}: the pipeline service launcher ({@code watch} for the directory mode,
 * {@code kafka} for the Kafka mode, {@code send}, {@code tail} and {@code republish} around it).
 */
@Command(name = "trajeval-pipeline", mixinStandardHelpOptions = true, versionProvider = PipelineCommand.VersionProvider.class,
        description = "Turns finished robot runs into metric reports, from a folder or from Kafka.",
        exitCodeListHeading = "%nExit codes:%n",
        exitCodeList = {"0:success (watch --drain: every bundle succeeded); also watch and kafka stopped by SIGTERM/SIGINT", "1:internal error",
            "2:bad configuration or usage", "4:watch --drain: some bundles were put in failed/",
            "5:kafka: no broker answered within --startup-timeout (send, tail: within 60 s)",
            "6:kafka: the broker refused this client (credentials, TLS certificate, permissions)",
            "7:watch --drain: work left unfinished because the service's own disk or folders failed (full, "
                + "read-only); the bundles stay in processing/ or incoming/ and are retried at the next start"})
public final class PipelineCommand implements Runnable {
    /** The subcommands, in the order of the help text. */
    private static final List<Class<?>> SUBCOMMANDS = List.of(Watch.class, KafkaCmd.class, Send.class, Tail.class,
            Republish.class, ConfigCmd.class);

    /** Exit code of {@code watch --drain} when some bundles failed. */
    public static final int SOME_FAILED = 4;

    private final Function<PipelineConfig, RunScorer> scorers;
    private final Map<String, String> env;

    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    /**
     * @param scorers builds the scorer from the configuration (the real one: {@link CoreRunScorer})
     * @param env environment variables for overrides
     */
    public PipelineCommand(Function<PipelineConfig, RunScorer> scorers, Map<String, String> env) {
        this.scorers = scorers;
        this.env = env;
    }

    @Override
    public void run() {
        throw new CommandLine.ParameterException(spec.commandLine(), "a subcommand is required (watch, kafka, send, tail, republish)");
    }

    /** Entry point of the launcher. */
    public static void main(String[] args) {
        System.exit(newCommandLine(c -> new CoreRunScorer(c.limits().maxFileBytes()), System.getenv(), args).execute(args));
    }

    /** @return the configured command line, every subcommand in it */
    public static CommandLine newCommandLine(Function<PipelineConfig, RunScorer> scorers, Map<String, String> env) {
        return newCommandLine(scorers, env, new String[0]);
    }

    /**
     * @param args the arguments it will run: when the first names a subcommand, only that one is put in
     *     picocli's model (picocli reads every option of a subcommand when it is added: issue 15, part of
     *     the service's start); otherwise (help, version, usage errors) every subcommand, in help order
     * @return the configured command line
     */
    public static CommandLine newCommandLine(Function<PipelineConfig, RunScorer> scorers, Map<String, String> env,
            String[] args) {
        CommandLine cl = new CommandLine(new PipelineCommand(scorers, env));
        Class<?> invoked = null;
        for (Class<?> c : SUBCOMMANDS) {
            if (args.length > 0 && c.getAnnotation(Command.class).name().equals(args[0])) {
                invoked = c;
            }
        }
        for (Class<?> c : invoked == null ? SUBCOMMANDS : List.of(invoked)) {
            cl.addSubcommand(c);
        }
        cl.setExecutionExceptionHandler((ex, c, parsed) -> {
            PrintWriter err = c.getErr();
            if (ex instanceof BrokerFailure f) {
                err.println("trajeval-pipeline: " + f.getMessage());
                err.flush();
                return f.kind().exitCode();
            }
            if (ex instanceof InputException || ex instanceof IllegalArgumentException
                    || ex instanceof java.io.UncheckedIOException || ex instanceof org.trajeval.store.StoreException) {
                err.println("trajeval-pipeline: " + ex.getMessage());
                err.flush();
                return 2;
            }
            err.println("trajeval-pipeline: internal error: " + ex);
            ex.printStackTrace(err);
            err.flush();
            return 1;
        });
        cl.setParameterExceptionHandler((ex, unparsed) -> {
            ex.getCommandLine().getErr().println("trajeval-pipeline: " + ex.getMessage());
            ex.getCommandLine().getErr().println("Try '" + ex.getCommandLine().getCommandSpec().qualifiedName()
                    + " --help' for usage.");
            return 2;
        });
        return cl;
    }

    /** Options shared by every mode. */
    static class Common {
        @Option(names = "--config", paramLabel = "FILE", description = "YAML configuration file.")
        Path config;

        @Option(names = "--root", paramLabel = "DIR", description = "Root folder (incoming/, reports/, ...).")
        String root;

        @Option(names = "--workers", paramLabel = "N", description = "Worker threads.")
        Integer workers;

        @Option(names = "--log-format", paramLabel = "text|json", description = "Log lines as text or JSON.")
        String logFormat;

        @Option(names = "--http-port", paramLabel = "PORT", description = "Port of /metrics and /health (0: free port).")
        Integer httpPort;

        @Option(names = "--no-http", description = "Do not serve /metrics and /health.")
        boolean noHttp;

        @Option(names = "--set", paramLabel = "KEY=VALUE", description = "Override any key, e.g. kafka.group_id=g1.")
        Map<String, String> set = new LinkedHashMap<>();

        PipelineConfig load(Map<String, String> env) {
            Map<String, String> o = new LinkedHashMap<>(set);
            if (root != null) {
                o.put("root", root);
            }
            if (workers != null) {
                o.put("workers", workers.toString());
            }
            if (logFormat != null) {
                o.put("log_format", logFormat);
            }
            if (httpPort != null) {
                o.put("http.port", httpPort.toString());
            }
            if (noHttp) {
                o.put("http.enabled", "false");
            }
            PipelineConfig c = ConfigLoader.load(config, env, o);
            LogFormat.of(c.logFormat()).apply();
            return c;
        }
    }

    /** {@code watch}: the directory mode. */
    @Command(name = "watch", mixinStandardHelpOptions = true,
            description = "Processes run bundles dropped in ROOT/incoming/ until stopped (or, with --drain, until none is left). "
                    + "SIGTERM/SIGINT finishes the runs in hand and exits 0.")
    static final class Watch extends Common implements Callable<Integer> {
        @CommandLine.ParentCommand
        PipelineCommand parent;

        @CommandLine.Spec
        CommandLine.Model.CommandSpec spec;

        @Option(names = "--drain", description = "Process every complete bundle present, then exit (0: all succeeded, 4: some failed, "
                + "7: work left unfinished: disk full or a read-only folder).")
        boolean drain;

        @Override
        public Integer call() {
            PipelineConfig c = load(parent.env);
            DirectoryLayout layout = new DirectoryLayout(c.rootPath()).create();
            // the Prometheus registry only when its endpoint will serve it (not in a drain, not with http off):
            // otherwise the same meters in memory, without the registry's start-up (about 0.1 s of a drain's start)
            boolean served = c.http().enabled() && !drain;
            PipelineMetrics metrics = served ? PipelineMetrics.prometheus() : PipelineMetrics.inMemory();
            try (Ledger ledger = Ledger.open(layout.ledger())) {
                ResultsRecorder.Attached store = ResultsRecorder.attach(c,
                        new ReportStore(layout.reports(), ledger, Clock.systemUTC()), metrics.storeLag(), parent.env);
                RunProcessor processor = new RunProcessor(parent.scorers.apply(c), store.reports());
                DirectoryService service = new DirectoryService(layout, c.directoryOptions(), processor,
                        new BundleOpener(c.bundleLimits(), c.bagSettings()), metrics, Clock.systemUTC());
                HttpEndpoint http = served
                        ? HttpEndpoint.start(c.http().host(), c.http().port(), metrics::scrape, service::isRunning) : null;
                // SIGTERM / SIGINT: stop claiming, finish the runs in hand, print the summary, exit
                // normally (0, or --drain's code). The hook covers the other ways the JVM shuts down.
                CountDownLatch finished = new CountDownLatch(1);
                Thread hook = new Thread(() -> {
                    service.stop();
                    try {
                        finished.await(120, TimeUnit.SECONDS);
                    } catch (InterruptedException e) {
                        Thread.currentThread().interrupt();
                    }
                }, "trajeval-shutdown");
                Runtime.getRuntime().addShutdownHook(hook);
                DrainSummary s;
                try (StopSignals signals = StopSignals.install(service::stop)) {
                    s = drain ? service.drain() : service.runUntilStopped();
                } finally {
                    if (http != null) {
                        http.close();
                    }
                    if (store.recorder() != null) {
                        store.recorder().close();
                    }
                    finished.countDown();
                }
                try {
                    Runtime.getRuntime().removeShutdownHook(hook);
                } catch (IllegalStateException shuttingDown) {
                    // the JVM is shutting down (not by SIGTERM/SIGINT): the hook is running and waits for us
                }
                PrintWriter out = spec.commandLine().getOut();
                out.printf("reported=%d duplicates=%d failed=%d unfinished=%d%n", s.reported(), s.duplicates(), s.failed(),
                        s.unfinished());
                out.flush();
                return drain ? s.exitCode() : 0;
            }
        }
    }

    /** Options of every subcommand that talks to Kafka without running the service: configuration and broker. */
    static class KafkaClientOptions {
        @Option(names = "--config", paramLabel = "FILE", description = "YAML configuration file (its kafka.* keys apply).")
        Path config;

        @Option(names = "--bootstrap-servers", paramLabel = "HOST:PORT", description = "Kafka cluster (default: kafka.bootstrap_servers, 127.0.0.1:9092).")
        String bootstrap;

        @Option(names = "--set", paramLabel = "KEY=VALUE", description = "Override any key, e.g. kafka.output_topic=t.")
        Map<String, String> set = new LinkedHashMap<>();

        PipelineConfig load(Map<String, String> env) {
            Map<String, String> o = new LinkedHashMap<>(set);
            if (bootstrap != null) {
                o.put("kafka.bootstrap_servers", bootstrap);
            }
            return ConfigLoader.load(config, env, o);
        }
    }

    /** {@code kafka}: the Kafka mode (Kafka classes are loaded only here). */
    @Command(name = "kafka", mixinStandardHelpOptions = true,
            description = "Consumes run events from the input topic, writes reports, publishes report events. "
                    + "Rides out broker outages; SIGTERM finishes the current transaction and exits 0.")
    static final class KafkaCmd extends Common implements Callable<Integer> {
        @CommandLine.ParentCommand
        PipelineCommand parent;

        @Option(names = "--bootstrap-servers", paramLabel = "HOST:PORT", description = "Kafka cluster to use.")
        String bootstrap;

        @Option(names = "--startup-timeout", paramLabel = "SECONDS",
                description = "Exit with code 5 when no broker answers within this time (s; default: wait forever).")
        Double startupTimeout;

        @Override
        public Integer call() throws InterruptedException {
            if (bootstrap != null) {
                set.put("kafka.bootstrap_servers", bootstrap);
            }
            if (startupTimeout != null) {
                set.put("kafka.startup_timeout_s", startupTimeout.toString());
            }
            PipelineConfig c = load(parent.env);
            return KafkaMode.run(c, parent.scorers.apply(c), KafkaClients.of(c.kafka(), parent.env));
        }
    }

    /** {@code send}: publishes run event files to the input topic. */
    @Command(name = "send", mixinStandardHelpOptions = true,
            description = "Publishes run events (a JSON file each, or .jsonl with one per line), keyed by robot_id.")
    static final class Send extends KafkaClientOptions implements Callable<Integer> {
        @CommandLine.ParentCommand
        PipelineCommand parent;

        @CommandLine.Spec
        CommandLine.Model.CommandSpec spec;

        @Option(names = "--topic", description = "Topic (default: kafka.input_topic, trajeval.runs).")
        String topic;

        @CommandLine.Parameters(paramLabel = "FILE", arity = "1..*", description = "Event files.")
        java.util.List<Path> files;

        @Override
        public Integer call() {
            PipelineConfig c = load(parent.env);
            String t = topic == null ? c.kafka().inputTopic() : topic;
            int n = KafkaMode.send(KafkaClients.of(c.kafka(), parent.env), t, files);
            spec.commandLine().getOut().println("sent " + n + " event(s) to " + t);
            spec.commandLine().getOut().flush();
            return 0;
        }
    }

    /** {@code tail}: prints a topic's committed records (report events, dead letters). */
    @Command(name = "tail", mixinStandardHelpOptions = true,
            description = "Prints the committed records of a topic from its beginning for a few seconds.")
    static final class Tail extends KafkaClientOptions implements Callable<Integer> {
        @CommandLine.ParentCommand
        PipelineCommand parent;

        @CommandLine.Spec
        CommandLine.Model.CommandSpec spec;

        @Option(names = "--topic", description = "Topic (default: kafka.output_topic, trajeval.reports).")
        String topic;

        @Option(names = "--seconds", defaultValue = "5", description = "How long to read (default: ${DEFAULT-VALUE} s).")
        int seconds;

        @Override
        public Integer call() {
            PipelineConfig c = load(parent.env);
            KafkaMode.tail(KafkaClients.of(c.kafka(), parent.env), topic == null ? c.kafka().outputTopic() : topic, seconds,
                    spec.commandLine().getOut());
            return 0;
        }
    }

    /** {@code republish}: publishes report events again from the ledger. */
    @Command(name = "republish", mixinStandardHelpOptions = true,
            description = "Publishes the report events of every run reported since a time again, from ROOT's ledger "
                    + "and report files (consumers drop repeats by run_id and content_sha256).")
    static final class Republish extends KafkaClientOptions implements Callable<Integer> {
        @CommandLine.ParentCommand
        PipelineCommand parent;

        @CommandLine.Spec
        CommandLine.Model.CommandSpec spec;

        @Option(names = "--root", paramLabel = "DIR", description = "The service's root folder.")
        String root;

        @Option(names = "--since", required = true, paramLabel = "TIME",
                description = "ISO-8601 instant (2026-11-23T08:00:00Z) or 'all'.")
        String since;

        @Override
        public Integer call() {
            if (root != null) {
                set.put("root", root);
            }
            PipelineConfig c = load(parent.env);
            java.time.Instant from;
            try {
                from = "all".equals(since) ? java.time.Instant.EPOCH : java.time.Instant.parse(since);
            } catch (java.time.format.DateTimeParseException e) {
                throw new CommandLine.ParameterException(spec.commandLine(),
                        "--since must be an ISO-8601 instant such as 2026-11-23T08:00:00Z, or 'all', found \"" + since + "\"");
            }
            int n = KafkaMode.republish(c, KafkaClients.of(c.kafka(), parent.env), from);
            spec.commandLine().getOut().println("re-published " + n + " report event(s) to " + c.kafka().outputTopic());
            spec.commandLine().getOut().flush();
            return 0;
        }
    }

    /** {@code config --show}: the effective configuration, secrets masked. */
    @Command(name = "config", mixinStandardHelpOptions = true,
            description = "Prints the effective configuration (defaults, file, environment, options) and the Kafka "
                    + "client settings every client gets, with secrets masked.")
    static final class ConfigCmd extends Common implements Callable<Integer> {
        @CommandLine.ParentCommand
        PipelineCommand parent;

        @CommandLine.Spec
        CommandLine.Model.CommandSpec spec;

        @Option(names = "--show", required = true, description = "Print the effective configuration.")
        boolean show;

        @Override
        public Integer call() {
            PipelineConfig c = load(parent.env);
            PrintWriter out = spec.commandLine().getOut();
            out.print(ConfigLoader.toYaml(c));
            out.println("# Kafka client settings applied to every client (secrets masked):");
            out.println("bootstrap.servers=" + c.kafka().bootstrapServers());
            org.trajeval.pipeline.kafka.ClientSettings.of(c.kafka(), parent.env).masked()
                    .forEach((k, v) -> out.println(k + "=" + v));
            out.flush();
            return 0;
        }
    }

    /** Prints the tool version. */
    static final class VersionProvider implements CommandLine.IVersionProvider {
        @Override
        public String[] getVersion() {
            return new String[] {"trajeval-pipeline " + Version.TOOL};
        }
    }
}
