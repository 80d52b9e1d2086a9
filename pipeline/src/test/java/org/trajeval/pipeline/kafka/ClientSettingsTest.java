package org.trajeval.pipeline.kafka;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.pipeline.ConfigLoader;
import org.trajeval.pipeline.PipelineConfig;

class ClientSettingsTest {
    @TempDir
    Path dir;

    private static PipelineConfig.Kafka kafka(Map<String, String> overrides) {
        return ConfigLoader.load(null, Map.of(), overrides).kafka();
    }

    @Test
    void everyExamplePropertiesFileOfTheReadmeLoadsAndKeepsItsReferences() throws Exception {
        Path docs = Path.of(System.getProperty("trajeval.projectDir", ".")).getParent().resolve("docs/kafka");
        for (String f : new String[] {"confluent-cloud", "event-hubs", "msk-scram", "msk-mtls"}) {
            ClientSettings s = ClientSettings.of(kafka(Map.of("kafka.client_properties",
                    docs.resolve(f + ".properties").toString())), Map.of());
            assertTrue(s.settings().get("security.protocol").startsWith("S"), f);
            assertTrue(s.secrets().isEmpty(), f + ": the example files hold no secret, only ${env:...} references");
            assertEquals(s.settings(), s.masked(), f + ": references are shown as they are");
        }
    }

    @Test
    void aKeyTheServiceOwnsIsRefusedNamingIt() throws Exception {
        Path f = dir.resolve("client.properties");
        Files.writeString(f, "security.protocol=SSL\nisolation.level=read_uncommitted\n");
        InputException e = assertThrows(InputException.class,
                () -> ClientSettings.of(kafka(Map.of("kafka.client_properties", f.toString())), Map.of()));
        assertEquals("isolation.level", e.column());
        assertEquals(InputProblem.INVALID_CONFIGURATION, e.problem());
        assertTrue(e.getMessage().contains("read_committed"), e.getMessage());
    }

    @Test
    void shortcutsResolveReferencesAndMaskThem() throws Exception {
        Path pw = dir.resolve("pw");
        Files.writeString(pw, "s3cret-from-file\n"); // the trailing newline is not part of the password
        Path trust = Files.writeString(dir.resolve("ca.p12"), "x");
        ClientSettings s = ClientSettings.of(kafka(Map.of("kafka.security.protocol", "sasl_ssl",
                "kafka.security.sasl_mechanism", "SCRAM-SHA-512", "kafka.security.sasl_username", "u1",
                "kafka.security.sasl_password", "file:" + pw, "kafka.security.truststore", trust.toString(),
                "kafka.security.truststore_password", "env:TRUST")), Map.of("TRUST", "trust-pass"));
        assertEquals("SASL_SSL", s.settings().get("security.protocol"));
        assertEquals("org.apache.kafka.common.security.scram.ScramLoginModule required username=\"u1\" "
                + "password=\"s3cret-from-file\";", s.settings().get("sasl.jaas.config"));
        assertEquals("trust-pass", s.settings().get("ssl.truststore.password"));
        String shown = s.masked().toString();
        assertFalse(shown.contains("s3cret") || shown.contains("trust-pass"), shown);
        assertTrue(shown.contains("username=\"u1\" password=\"****\""), shown);
        assertEquals("error at **** for u1", s.scrub("error at s3cret-from-file for u1"));
    }

    @Test
    void aLiteralSecretOrAnUnsetVariableIsRefusedWithoutEchoingTheValue() {
        InputException literal = assertThrows(InputException.class, () -> ClientSettings.of(kafka(Map.of(
                "kafka.security.sasl_mechanism", "PLAIN", "kafka.security.sasl_username", "u",
                "kafka.security.sasl_password", "hunter2")), Map.of()));
        assertFalse(literal.getMessage().contains("hunter2"), literal.getMessage());
        assertEquals("kafka.security.sasl_password", literal.column());
        InputException unset = assertThrows(InputException.class, () -> ClientSettings.of(kafka(Map.of(
                "kafka.security.sasl_mechanism", "PLAIN", "kafka.security.sasl_username", "u",
                "kafka.security.sasl_password", "env:NOPE")), Map.of()));
        assertTrue(unset.getMessage().contains("NOPE, which is not set"), unset.getMessage());
    }
}
