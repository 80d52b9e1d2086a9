package org.trajeval.spark;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.File;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.ServerSocket;
import java.net.URL;
import java.net.URLConnection;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A real standalone cluster on the loopback address: a Master and two Workers (spark-core's own
 * classes, each its own JVM, free ports), SPARK_HOME a temporary folder with an empty RELEASE and
 * jars/ holding Spark's jars only; the module's submit jar goes in through SparkSubmit (client
 * mode). One worker is killed (with its executor, as a machine that dies) while the job runs;
 * Spark reruns the lost tasks on the other and the output holds each pair exactly once.
 * Alone: gradle :spark:junitTest -Djunit.include='.*StandaloneCluster.*'
 */
@Tag("spark-cluster")
class StandaloneClusterTest {
    private static final int PAIRS = 24;
    private static final long JOB_LIMIT_S = 150;

    @TempDir
    Path tmp;

    private final List<Process> started = new ArrayList<>();

    @AfterEach
    void stopEverything() {
        for (Process p : started) {
            p.descendants().forEach(ProcessHandle::destroyForcibly);
            p.destroyForcibly();
        }
    }

    @Test
    void aWorkerKilledWhileTheJobRunsLeavesEachPairExactlyOnceInTheOutput() throws Exception {
        Path home = sparkHome();
        int masterPort = freePort();
        int masterUi = freePort();
        String master = "spark://127.0.0.1:" + masterPort;
        start(home, "master", List.of("org.apache.spark.deploy.master.Master", "--host", "127.0.0.1",
                "--port", Integer.toString(masterPort), "--webui-port", Integer.toString(masterUi)));
        Path work1 = Files.createDirectories(tmp.resolve("work1"));
        Path work2 = Files.createDirectories(tmp.resolve("work2"));
        Process worker1 = start(home, "worker1", worker(work1, master));
        start(home, "worker2", worker(work2, master));
        // both workers registered before the job is submitted (the Master's UI JSON), however loaded the machine
        long registered = System.nanoTime() + TimeUnit.SECONDS.toNanos(JOB_LIMIT_S);
        while (aliveWorkers(masterUi) < 2) {
            assertTrue(System.nanoTime() < registered, "two workers registered with the Master within "
                    + JOB_LIMIT_S + " s: " + Files.readString(tmp.resolve("master.log")));
            Thread.sleep(200);
        }

        // pairs heavy enough (fr2_desk: 20 957 reference poses) that the job is still running when a worker dies
        Path pairs = tmp.resolve("pairs.csv");
        StringBuilder csv = new StringBuilder("ref,est,pair_id\n");
        for (int i = 0; i < PAIRS; i++) {
            csv.append(data("fr2_desk_groundtruth.txt")).append(',').append(data(i % 2 == 0 ? "fr2_desk_ORB.txt"
                    : "fr2_desk_ORB_kf_mono.txt")).append(',').append(i).append('\n');
        }
        Files.writeString(pairs, csv);
        Path out = tmp.resolve("out");
        List<String> submit = new ArrayList<>(List.of("org.apache.spark.deploy.SparkSubmit", "--master", master,
                "--deploy-mode", "client", "--class", SparkJob.class.getName(),
                "--conf", "spark.driver.host=127.0.0.1", "--conf", "spark.driver.bindAddress=127.0.0.1",
                "--conf", "spark.ui.enabled=false", "--conf", "spark.executor.memory=512m",
                "--conf", "spark.executor.cores=1", "--conf", "spark.task.maxFailures=8",
                // no task is scheduled before both executors are up: worker 1 surely gets tasks to lose
                "--conf", "spark.cores.max=2", "--conf", "spark.scheduler.minRegisteredResourcesRatio=1.0",
                "--conf", "spark.scheduler.maxRegisteredResourcesWaitingTime=" + JOB_LIMIT_S + "s",
                System.getProperty("trajeval.submitJar"),
                "score", "--pairs", pairs.toString(), "--out", out.toString(), "--format", "json",
                "--partitions", "8", "--convention", "evo", "--align", "sim3"));
        Process driver = start(home, "driver", submit);

        // kill worker 1 (and its executor) once it runs a task of the job
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(JOB_LIMIT_S);
        while (!runsATask(work1)) {
            assertTrue(driver.isAlive() || runsATask(work1), "the job ended before worker 1 ran a task: "
                    + Files.readString(tmp.resolve("driver.log")));
            assertTrue(System.nanoTime() < deadline, "worker 1 never ran a task");
            Thread.sleep(100);
        }
        List<ProcessHandle> executors = worker1.descendants().toList();
        worker1.destroyForcibly();
        executors.forEach(ProcessHandle::destroyForcibly);

        assertTrue(driver.waitFor(JOB_LIMIT_S, TimeUnit.SECONDS), "job within " + JOB_LIMIT_S + " s");
        String driverLog = Files.readString(tmp.resolve("driver.log"));
        assertEquals(0, driver.exitValue(), driverLog);
        assertTrue(driverLog.contains("Lost executor") || driverLog.contains("ExecutorLostFailure")
                || driverLog.contains("Lost task"), "the driver saw the executor go:\n" + driverLog);

        ObjectMapper json = new ObjectMapper();
        List<String> ids = new ArrayList<>();
        try (Stream<Path> files = Files.list(out)) {
            for (Path f : files.filter(p -> p.getFileName().toString().endsWith(".json")).toList()) {
                for (String line : Files.readAllLines(f)) {
                    JsonNode row = json.readTree(line);
                    assertEquals(ResultSchema.OK, row.get(ResultSchema.STATUS).asText(), line);
                    assertTrue(row.get("ate_trans_rmse_m").asDouble() > 0);
                    ids.add(row.get("pair_id").asText());
                }
            }
        }
        Set<String> distinct = new HashSet<>(ids);
        assertEquals(PAIRS, ids.size(), "one row per pair: " + ids);
        assertEquals(PAIRS, distinct.size(), "each pair exactly once: " + ids);
    }

    private static List<String> worker(Path workDir, String master) throws IOException {
        return List.of("org.apache.spark.deploy.worker.Worker", "--host", "127.0.0.1", "--port",
                Integer.toString(freePort()), "--webui-port", Integer.toString(freePort()), "--cores", "1",
                "--memory", "1g", "--work-dir", workDir.toString(), master);
    }

    /** @return the number of ALIVE workers the Master's UI JSON lists (0 while the UI is not up) */
    private static int aliveWorkers(int uiPort) {
        try {
            URLConnection c = new URL("http://127.0.0.1:" + uiPort + "/json/").openConnection();
            c.setConnectTimeout(2000);
            c.setReadTimeout(5000);
            try (var in = c.getInputStream()) {
                JsonNode n = new ObjectMapper().readTree(in);
                return n.path("aliveworkers").asInt(0);
            }
        } catch (IOException e) {
            return 0; // the Master is still starting
        }
    }

    /** @return whether an executor under the worker's folder has started a task (its log says so) */
    private static boolean runsATask(Path workDir) throws IOException {
        try (Stream<Path> s = Files.walk(workDir)) {
            return s.filter(p -> p.getFileName().toString().equals("stderr")).anyMatch(p -> {
                try {
                    return Files.readString(p).contains("Running task");
                } catch (IOException e) {
                    throw new UncheckedIOException(e);
                }
            });
        }
    }

    /** SPARK_HOME: an empty RELEASE file (a distribution, not a source tree) and jars/ with Spark's jars only. */
    private Path sparkHome() throws IOException {
        Path home = Files.createDirectories(tmp.resolve("spark-home"));
        Files.writeString(home.resolve("RELEASE"), "");
        Path jars = Files.createDirectories(home.resolve("jars"));
        for (String jar : System.getProperty("trajeval.sparkJars").split(File.pathSeparator)) {
            Path p = Path.of(jar);
            Files.createSymbolicLink(jars.resolve(p.getFileName()), p);
        }
        return home;
    }

    private Process start(Path home, String name, List<String> mainAndArgs) throws IOException {
        List<String> cmd = new ArrayList<>();
        cmd.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        cmd.add("-Xmx512m");
        cmd.addAll(List.of(System.getProperty("trajeval.sparkJvmOptions").split(" ")));
        cmd.add("-Dlog4j2.configurationFile=" + System.getProperty("log4j2.configurationFile"));
        cmd.add("-Dspark.master.rest.enabled=false");
        cmd.add("-cp");
        cmd.add(home.resolve("jars") + File.separator + "*");
        cmd.addAll(mainAndArgs);
        ProcessBuilder pb = new ProcessBuilder(cmd).redirectErrorStream(true)
                .redirectOutput(tmp.resolve(name + ".log").toFile());
        pb.environment().put("SPARK_HOME", home.toString());
        pb.environment().put("SPARK_SCALA_VERSION", "2.13");
        pb.environment().put("SPARK_LOCAL_IP", "127.0.0.1");
        Process p = pb.start();
        started.add(p);
        return p;
    }

    private static int freePort() throws IOException {
        try (ServerSocket s = new ServerSocket(0, 1, java.net.InetAddress.getLoopbackAddress())) {
            return s.getLocalPort();
        }
    }

    private static String data(String name) {
        return LocalSpark.refdata().resolve(name).toString();
    }
}
