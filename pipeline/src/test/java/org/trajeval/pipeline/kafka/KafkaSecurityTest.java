package org.trajeval.pipeline.kafka;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.SecureRandom;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HexFormat;
import java.util.List;
import java.util.Map;
import java.util.Properties;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.apache.kafka.clients.admin.Admin;
import org.apache.kafka.clients.admin.ScramCredentialInfo;
import org.apache.kafka.clients.admin.ScramMechanism;
import org.apache.kafka.clients.admin.UserScramCredentialUpsertion;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInstance;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.pipeline.PipelineCommand;
import org.trajeval.pipeline.StandInScorer;
import picocli.CommandLine;

/**
 * A broker (own JVM) with a SASL_SSL listener (SCRAM-SHA-512) and a mutual-TLS listener, on
 * certificates made by keytool for this run. The right credentials score runs exactly once
 * (the service over mTLS with the README's msk-mtls.properties; events sent over SASL_SSL with the
 * typed shortcuts; reports read back with msk-scram.properties); wrong password, missing
 * truststore, a mechanism the broker does not offer, no client certificate and a PLAINTEXT
 * client are refused with one line and a documented exit code; no output holds a secret.
 */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class KafkaSecurityTest {
    private static final String USER = "trajeval";
    private static final int RUNS = 5;

    private Path tmp;
    private TestCertificates certs;
    private BrokerProcess broker;
    private String password;
    private String sasl;
    private String mtls;
    private final List<String> outputs = new ArrayList<>();

    @BeforeAll
    void startSecuredBroker(@TempDir Path dir) throws Exception {
        tmp = dir;
        SecureRandom rnd = new SecureRandom();
        byte[] b = new byte[12];
        rnd.nextBytes(b);
        password = "scram-" + HexFormat.of().formatHex(b);
        rnd.nextBytes(b);
        certs = TestCertificates.generate(tmp.resolve("certs"), "store-" + HexFormat.of().formatHex(b));
        Path conf = tmp.resolve("broker.properties");
        Properties p = new Properties();
        p.setProperty("listener.security.protocol.map", "CLIENT:SASL_SSL,INTERNAL:PLAINTEXT,CONTROLLER:PLAINTEXT,MTLS:SSL");
        p.setProperty("sasl.enabled.mechanisms", "SCRAM-SHA-512");
        p.setProperty("listener.name.client.scram-sha-512.sasl.jaas.config",
                "org.apache.kafka.common.security.scram.ScramLoginModule required;");
        p.setProperty("ssl.keystore.location", certs.brokerKeystore().toString());
        p.setProperty("ssl.keystore.password", certs.password());
        p.setProperty("ssl.key.password", certs.password());
        p.setProperty("ssl.keystore.type", "PKCS12");
        p.setProperty("listener.name.mtls.ssl.client.auth", "required");
        p.setProperty("listener.name.mtls.ssl.truststore.location", certs.truststore().toString());
        p.setProperty("listener.name.mtls.ssl.truststore.password", certs.password());
        try (var w = Files.newBufferedWriter(conf)) {
            p.store(w, null);
        }
        broker = BrokerProcess.start(tmp.resolve("broker-data"), tmp.resolve("broker.log"), conf, List.of("MTLS"));
        sasl = broker.bootstrapServers();
        mtls = broker.bootstrapServers("MTLS");
        BrokerMain.createTopics(broker.internalBootstrapServers(), RunEvents.TOPICS);
        try (Admin admin = Admin.create(Map.of("bootstrap.servers", broker.internalBootstrapServers()))) {
            admin.alterUserScramCredentials(List.of(new UserScramCredentialUpsertion(USER,
                    new ScramCredentialInfo(ScramMechanism.SCRAM_SHA_512, 8192), password))).all().get(60, TimeUnit.SECONDS);
            while (admin.describeUserScramCredentials(List.of(USER)).all().get(30, TimeUnit.SECONDS).isEmpty()) {
                Thread.sleep(100);
            }
        }
    }

    @AfterAll
    void stopBroker() throws Exception {
        if (broker != null) {
            broker.close();
        }
    }

    /** The typed shortcuts for SCRAM over TLS with the test CA (password from the environment). */
    private List<String> scramShortcuts(String bootstrap, String passwordVar) {
        return List.of("--bootstrap-servers", bootstrap, "--set", "kafka.security.protocol=SASL_SSL",
                "--set", "kafka.security.sasl_mechanism=SCRAM-SHA-512", "--set", "kafka.security.sasl_username=" + USER,
                "--set", "kafka.security.sasl_password=env:" + passwordVar,
                "--set", "kafka.security.truststore=" + certs.truststore(),
                "--set", "kafka.security.truststore_password=env:STORE_PASSWORD");
    }

    private Map<String, String> env() {
        return Map.of("SCRAM_PASSWORD", password, "WRONG_PASSWORD", "not-" + password, "STORE_PASSWORD",
                certs.password());
    }

    /** Runs the launcher in this JVM: @return exit code, and the output (stdout + stderr) in {@code out} */
    private int launch(StringWriter out, List<String> args) {
        CommandLine cl = PipelineCommand.newCommandLine(c -> new StandInScorer(), env());
        cl.setOut(new PrintWriter(out));
        cl.setErr(new PrintWriter(out));
        int code = cl.execute(args.toArray(String[]::new));
        outputs.add(out.toString());
        if (code != 0) {
            System.out.println("exit " + code + ": " + out.toString().trim()); // the README's table of refusals
        }
        return code;
    }

    private List<String> kafka(String root, List<String> more) {
        List<String> a = new ArrayList<>(List.of("kafka", "--root", tmp.resolve(root).toString(), "--no-http",
                "--startup-timeout", "6"));
        a.addAll(more);
        return a;
    }

    @Test
    void rightCredentialsScoreRunsExactlyOnceOverMutualTlsAndScram() throws Exception {
        Path root = tmp.resolve("svc");
        Map<String, String> childEnv = new HashMap<>(Map.of("KAFKA_KEYSTORE", certs.clientKeystore().toString(),
                "KAFKA_KEYSTORE_PASSWORD", certs.password(), "STORE_PASSWORD", certs.password(),
                "KAFKA_USERNAME", USER, "KAFKA_PASSWORD", password));
        Path docs = Path.of(System.getProperty("trajeval.projectDir", ".")).getParent().resolve("docs/kafka");
        String trust = "kafka.security.truststore=" + certs.truststore();
        String trustPassword = "kafka.security.truststore_password=env:STORE_PASSWORD";
        try (ServiceProcess svc = ServiceProcess.start(root, mtls, tmp.resolve("service.log"), List.of(
                "--set", "kafka.client_properties=" + docs.resolve("msk-mtls.properties"), "--set", trust,
                "--set", trustPassword, "--set", "kafka.group_id=secure"), childEnv)) {
            Path events = tmp.resolve("events.jsonl");
            StringBuilder lines = new StringBuilder();
            for (int i = 0; i < RUNS; i++) {
                lines.append(RunEvents.event(i)).append('\n');
            }
            lines.append("{\"run_id\": \"broken\"}\n"); // a dead letter, scanned for secrets below
            Files.writeString(events, lines);
            List<String> send = new ArrayList<>(List.of("send"));
            send.addAll(scramShortcuts(sasl, "SCRAM_PASSWORD"));
            send.add(events.toString());
            StringWriter sent = new StringWriter();
            assertEquals(0, launch(sent, send), sent.toString());
            long deadline = System.nanoTime() + Duration.ofSeconds(90).toNanos();
            while (RunEvents.reportFiles(root.resolve("reports")).size() < RUNS && System.nanoTime() < deadline) {
                Thread.sleep(100);
            }
            assertEquals(RunEvents.files(RunEvents.ids(0, RUNS)), RunEvents.reportFiles(root.resolve("reports")),
                    svc.log());
            // read back over SASL_SSL with the README's msk-scram.properties, in a child JVM (its env has the password)
            String tail = child(List.of("tail", "--bootstrap-servers", sasl, "--seconds", "4",
                    "--set", "kafka.client_properties=" + docs.resolve("msk-scram.properties"), "--set", trust,
                    "--set", trustPassword), childEnv);
            Map<String, Long> perRun = tail.lines().filter(l -> l.startsWith("{\"run_id\""))
                    .map(l -> l.substring(11, l.indexOf('"', 11))).collect(Collectors.groupingBy(s -> s, Collectors.counting()));
            assertEquals(RunEvents.ids(0, RUNS), perRun.keySet(), tail);
            assertTrue(perRun.values().stream().allMatch(n -> n == 1), "exactly one report event per run: " + perRun);
            outputs.add(tail);
            outputs.add(child(List.of("tail", "--bootstrap-servers", sasl, "--seconds", "3", "--topic", "trajeval.runs.dlq",
                    "--set", "kafka.client_properties=" + docs.resolve("msk-scram.properties"), "--set", trust,
                    "--set", trustPassword), childEnv));
            outputs.add(svc.metrics());
            outputs.add(svc.health());
            assertEquals(0, svc.terminate());
            outputs.add(svc.log());
        }
        try (Stream<Path> files = Files.walk(root)) {
            for (Path f : files.filter(Files::isRegularFile).toList()) {
                outputs.add(Files.readString(f, StandardCharsets.ISO_8859_1));
            }
        }
        assertNoSecretIn(outputs);
    }

    private String child(List<String> args, Map<String, String> env) throws IOException, InterruptedException {
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Xmx128m", "-XX:TieredStopAtLevel=1", "-cp",
                System.getProperty("trajeval.testClasspath", System.getProperty("java.class.path")),
                PipelineCommand.class.getName()));
        cmd.addAll(args);
        ProcessBuilder pb = new ProcessBuilder(cmd).redirectErrorStream(true);
        pb.environment().putAll(env);
        Process p = pb.start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(60, TimeUnit.SECONDS));
        assertEquals(0, p.exitValue(), out);
        return out;
    }

    @Test
    void wrongPasswordIsRefusedWithOneLineNamingBrokerMechanismAndUser() {
        StringWriter out = new StringWriter();
        assertEquals(6, launch(out, kafka("wrong", scramShortcuts(sasl, "WRONG_PASSWORD"))), out.toString());
        String line = out.toString().trim();
        assertEquals(1, line.lines().count(), line);
        assertTrue(line.startsWith("trajeval-pipeline: Kafka broker " + sasl + " refused the connection: SASL "
                + "authentication failed (security protocol SASL_SSL, mechanism SCRAM-SHA-512, user 'trajeval')"), line);
    }

    @Test
    void missingTruststoreFailsTheTlsHandshakeWithOneLine() {
        List<String> noTrust = new ArrayList<>(scramShortcuts(sasl, "SCRAM_PASSWORD").subList(0, 10));
        StringWriter out = new StringWriter();
        assertEquals(6, launch(out, kafka("notrust", noTrust)), out.toString());
        assertTrue(out.toString().trim().lines().count() == 1 && out.toString().contains("the TLS handshake failed"),
                out.toString());
    }

    @Test
    void mechanismTheBrokerDoesNotOfferIsRefused() {
        List<String> a = new ArrayList<>(scramShortcuts(sasl, "SCRAM_PASSWORD"));
        a.set(a.indexOf("kafka.security.sasl_mechanism=SCRAM-SHA-512"), "kafka.security.sasl_mechanism=SCRAM-SHA-256");
        StringWriter out = new StringWriter();
        assertEquals(6, launch(out, kafka("mech", a)), out.toString());
        assertTrue(out.toString().contains("mechanism SCRAM-SHA-256, user 'trajeval'"), out.toString());
    }

    @Test
    void mutualTlsWithoutAClientCertificateIsRefused() {
        StringWriter out = new StringWriter();
        assertEquals(6, launch(out, kafka("nocert", List.of("--bootstrap-servers", mtls,
                "--set", "kafka.security.protocol=SSL", "--set", "kafka.security.truststore=" + certs.truststore(),
                "--set", "kafka.security.truststore_password=env:STORE_PASSWORD"))), out.toString());
        assertTrue(out.toString().contains("refused the connection"), out.toString());
    }

    @Test
    void plaintextClientToTheSecuredListenerExitsFiveNamingTheAddress() {
        StringWriter out = new StringWriter();
        assertEquals(5, launch(out, kafka("plain", List.of("--bootstrap-servers", sasl))), out.toString());
        assertTrue(out.toString().trim().startsWith("trajeval-pipeline: no Kafka broker answered at " + sasl + " within 6 s"),
                out.toString());
    }

    @Test
    void aPasswordOnTheCommandLineIsRefusedWithoutEchoingIt() {
        StringWriter out = new StringWriter();
        List<String> a = new ArrayList<>(scramShortcuts(sasl, "SCRAM_PASSWORD"));
        a.set(a.indexOf("kafka.security.sasl_password=env:SCRAM_PASSWORD"), "kafka.security.sasl_password=" + password);
        assertEquals(2, launch(out, kafka("literal", a)), out.toString());
        assertTrue(out.toString().contains("must be a reference, env:VARIABLE or file:PATH"), out.toString());
    }

    @Test
    void configShowMasksEverySecret() {
        StringWriter out = new StringWriter();
        List<String> a = new ArrayList<>(List.of("config", "--show"));
        a.addAll(scramShortcuts(sasl, "SCRAM_PASSWORD").subList(2, 14));
        assertEquals(0, launch(out, a), out.toString());
        assertTrue(out.toString().contains("password=\"****\""), out.toString());
        assertTrue(out.toString().contains("ssl.truststore.password=****"), out.toString());
        launch(new StringWriter(), List.of("kafka", "--help"));
        launch(new StringWriter(), List.of("config", "--help"));
        assertNoSecretIn(outputs);
    }

    private void assertNoSecretIn(List<String> texts) {
        Set<String> secrets = Set.of(password, certs.password());
        for (String t : texts) {
            for (String s : secrets) {
                assertFalse(t.contains(s), "a secret leaked into an output:\n" + t.replace(s, "<SECRET>"));
            }
        }
    }
}
