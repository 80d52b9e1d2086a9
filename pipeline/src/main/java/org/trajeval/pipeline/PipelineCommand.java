package org.trajeval.pipeline;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.time.Clock;
import java.util.LinkedHashMap;
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
import org.trajeval.pipeline.ledger.Ledger;
import org.trajeval.pipeline.metrics.HttpEndpoint;
import org.trajeval.pipeline.metrics.PipelineMetrics;
import org.trajeval.pipeline.store.ResultsRecorder;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * {@code trajeval-pipeline}: the pipeline service launcher ({@code watch} for the directory mode,
 * {@code kafka} for the Kafka mode, {@code broker} for a local single-node Kafka).
 */
@Command(name = "trajeval-pipeline", mixinStandardHelpOptions = true, versionProvider = PipelineCommand.VersionProvider.class,
        description = "Turns finished robot runs into metric reports, from a folder or from Kafka.",
        subcommands = {PipelineCommand.Watch.class, PipelineCommand.KafkaCmd.class, PipelineCommand.Broker.class,
            PipelineCommand.Send.class, PipelineCommand.Tail.class},
        exitCodeListHeading = "%nExit codes:%n",
        exitCodeList = {"0:success (watch --drain: every bundle succeeded)", "1:internal error",
            "2:bad configuration or usage", "4:watch --drain: some bundles were put in failed/"})
public final class PipelineCommand implements Runnable {
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
        throw new CommandLine.ParameterException(spec.commandLine(), "a subcommand is required (watch, kafka, broker)");
    }

    /** Entry point of the launcher. */
    public static void main(String[] args) {
        System.exit(newCommandLine(c -> new CoreRunScorer(c.limits().maxFileBytes()), System.getenv()).execute(args));
    }

    /** @return the configured command line */
    public static CommandLine newCommandLine(Function<PipelineConfig, RunScorer> scorers, Map<String, String> env) {
        CommandLine cl = new CommandLine(new PipelineCommand(scorers, env));
        cl.setExecutionExceptionHandler((ex, c, parsed) -> {
            PrintWriter err = c.getErr();
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
        cl.setParameterExceptionHandler((ex, args) -> {
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
            description = "Processes run bundles dropped in ROOT/incoming/ until stopped (or, with --drain, until none is left).")
    static final class Watch extends Common implements Callable<Integer> {
        @CommandLine.ParentCommand
        PipelineCommand parent;

        @CommandLine.Spec
        CommandLine.Model.CommandSpec spec;

        @Option(names = "--drain", description = "Process every complete bundle present, then exit (0: all succeeded, 4: some failed).")
        boolean drain;

        @Override
        public Integer call() {
            PipelineConfig c = load(parent.env);
            DirectoryLayout layout = new DirectoryLayout(c.rootPath()).create();
            PipelineMetrics metrics = PipelineMetrics.prometheus();
            try (Ledger ledger = Ledger.open(layout.ledger())) {
                ResultsRecorder.Attached store = ResultsRecorder.attach(c,
                        new ReportStore(layout.reports(), ledger, Clock.systemUTC()), metrics.storeLag(), parent.env);
                RunProcessor processor = new RunProcessor(parent.scorers.apply(c), store.reports());
                DirectoryService service = new DirectoryService(layout, c.directoryOptions(), processor,
                        new BundleOpener(c.bundleLimits()), metrics, Clock.systemUTC());
                HttpEndpoint http = c.http().enabled() && !drain
                        ? HttpEndpoint.start(c.http().host(), c.http().port(), metrics::scrape, service::isRunning) : null;
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
                try {
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
                    // SIGTERM: the hook is running and waits for us
                }
                PrintWriter out = spec.commandLine().getOut();
                out.printf("reported=%d duplicates=%d failed=%d%n", s.reported(), s.duplicates(), s.failed());
                out.flush();
                return drain ? s.exitCode() : 0;
            }
        }
    }

    /** {@code kafka}: the Kafka mode (Kafka classes are loaded only here). */
    @Command(name = "kafka", mixinStandardHelpOptions = true,
            description = "Consumes run events from the input topic, writes reports, publishes report events.")
    static final class KafkaCmd extends Common implements Callable<Integer> {
        @CommandLine.ParentCommand
        PipelineCommand parent;

        @Option(names = "--embedded-broker", description = "Start a single-node Kafka broker in this process (local runs).")
        boolean embeddedBroker;

        @Option(names = "--bootstrap-servers", paramLabel = "HOST:PORT", description = "Kafka cluster to use.")
        String bootstrap;

        @Override
        public Integer call() {
            if (bootstrap != null) {
                set.put("kafka.bootstrap_servers", bootstrap);
            }
            PipelineConfig c = load(parent.env);
            return org.trajeval.pipeline.kafka.KafkaMode.run(c, parent.scorers.apply(c), embeddedBroker);
        }
    }

    /** {@code broker}: a single-node Kafka broker for local trials. */
    @Command(name = "broker", mixinStandardHelpOptions = true,
            description = "Runs a single-node Kafka broker (KRaft) on 127.0.0.1 until stopped, for local trials.")
    static final class Broker implements Callable<Integer> {
        @CommandLine.Spec
        CommandLine.Model.CommandSpec spec;

        @Option(names = "--port", paramLabel = "PORT", description = "Client port (default: ${DEFAULT-VALUE}).")
        int port = 9092;

        @Option(names = "--data", paramLabel = "DIR", description = "Data folder (default: a temporary folder).")
        Path data;

        @Option(names = "--topics", split = ",", paramLabel = "NAME", description = "Topics to create (3 partitions each).")
        java.util.List<String> topics = java.util.List.of();

        @Override
        public Integer call() throws InterruptedException {
            return org.trajeval.pipeline.kafka.KafkaMode.runBroker(data, port, topics, spec.commandLine().getOut());
        }
    }

    /** {@code send}: publishes run event files to the input topic (local trials). */
    @Command(name = "send", mixinStandardHelpOptions = true,
            description = "Publishes run events (a JSON file each, or .jsonl with one per line), keyed by robot_id.")
    static final class Send implements Callable<Integer> {
        @CommandLine.Spec
        CommandLine.Model.CommandSpec spec;

        @Option(names = "--bootstrap-servers", paramLabel = "HOST:PORT", defaultValue = "127.0.0.1:9092",
                description = "Kafka cluster (default: ${DEFAULT-VALUE}).")
        String bootstrap;

        @Option(names = "--topic", defaultValue = "trajeval.runs", description = "Topic (default: ${DEFAULT-VALUE}).")
        String topic;

        @CommandLine.Parameters(paramLabel = "FILE", arity = "1..*", description = "Event files.")
        java.util.List<Path> files;

        @Override
        public Integer call() {
            int n = org.trajeval.pipeline.kafka.KafkaMode.send(bootstrap, topic, files);
            spec.commandLine().getOut().println("sent " + n + " event(s) to " + topic);
            spec.commandLine().getOut().flush();
            return 0;
        }
    }

    /** {@code tail}: prints a topic's committed records (report events, dead letters). */
    @Command(name = "tail", mixinStandardHelpOptions = true,
            description = "Prints the committed records of a topic from its beginning for a few seconds.")
    static final class Tail implements Callable<Integer> {
        @CommandLine.Spec
        CommandLine.Model.CommandSpec spec;

        @Option(names = "--bootstrap-servers", paramLabel = "HOST:PORT", defaultValue = "127.0.0.1:9092",
                description = "Kafka cluster (default: ${DEFAULT-VALUE}).")
        String bootstrap;

        @Option(names = "--topic", defaultValue = "trajeval.reports", description = "Topic (default: ${DEFAULT-VALUE}).")
        String topic;

        @Option(names = "--seconds", defaultValue = "5", description = "How long to read (default: ${DEFAULT-VALUE} s).")
        int seconds;

        @Override
        public Integer call() {
            org.trajeval.pipeline.kafka.KafkaMode.tail(bootstrap, topic, seconds, spec.commandLine().getOut());
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
