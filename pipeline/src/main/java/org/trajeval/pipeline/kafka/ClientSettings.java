package org.trajeval.pipeline.kafka;

import java.io.IOException;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.Locale;
import java.util.Map;
import java.util.Properties;
import java.util.Set;
import java.util.TreeMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.pipeline.PipelineConfig;

/**
 * The operator's Kafka client settings, applied to every client the service and its subcommands
 * build: first the client properties file ({@code kafka.client_properties}, Kafka's own format;
 * config providers such as {@code ${env:VAR}} are resolved by the Kafka client), then the typed
 * shortcuts ({@code kafka.security.*}), whose secrets are references ({@code env:VAR},
 * {@code file:PATH}) resolved here, in memory only. Keys the service sets itself are refused.
 *
 * @param settings the client settings (may hold secrets: never print them; {@link #masked()} is printable)
 * @param secrets the secret values resolved from references and read from the file (for scrubbing and tests)
 */
public record ClientSettings(Map<String, String> settings, Set<String> secrets) {
    /** Keys the service owns: the client properties file must not set them. */
    static final Map<String, String> OWNED = owned();

    private static final Pattern SECRET_KEY = Pattern.compile("(?i).*(password|secret|jaas|token|credential|\\.key$).*");
    private static final Pattern JAAS_PASSWORD = Pattern.compile("(password\\s*=\\s*)\"[^\"]*\"");
    private static final Set<String> PROTOCOLS = Set.of("PLAINTEXT", "SSL", "SASL_PLAINTEXT", "SASL_SSL");
    private static final Map<String, String> LOGIN_MODULES = Map.of(
            "PLAIN", "org.apache.kafka.common.security.plain.PlainLoginModule",
            "SCRAM-SHA-256", "org.apache.kafka.common.security.scram.ScramLoginModule",
            "SCRAM-SHA-512", "org.apache.kafka.common.security.scram.ScramLoginModule");

    /** @throws NullPointerException on null parts */
    public ClientSettings {
        settings = Collections.unmodifiableMap(new LinkedHashMap<>(settings));
        secrets = Set.copyOf(secrets);
    }

    /** @return no settings (PLAINTEXT, no file) */
    public static ClientSettings none() {
        return new ClientSettings(Map.of(), Set.of());
    }

    private static Map<String, String> owned() {
        Map<String, String> m = new LinkedHashMap<>();
        m.put("bootstrap.servers", "set kafka.bootstrap_servers instead");
        m.put("group.id", "set kafka.group_id instead");
        m.put("transactional.id", "the service derives it from kafka.group_id and kafka.instance_id");
        m.put("transaction.timeout.ms", "set kafka.transaction_timeout_ms instead");
        m.put("isolation.level", "the service reads with read_committed");
        m.put("enable.auto.commit", "the service commits offsets inside its transactions");
        m.put("enable.idempotence", "the service's producer is idempotent and transactional");
        m.put("key.serializer", "the service writes strings");
        m.put("value.serializer", "the service writes strings");
        m.put("key.deserializer", "the service reads strings");
        m.put("value.deserializer", "the service reads strings");
        return Collections.unmodifiableMap(m);
    }

    /**
     * Reads the client properties file and applies the shortcuts.
     *
     * @param k the Kafka settings
     * @param env the environment (for {@code env:} references)
     * @throws InputException naming the file or key, on an owned key, an unreadable file, a
     *     literal secret, an unset variable or a missing store file
     */
    public static ClientSettings of(PipelineConfig.Kafka k, Map<String, String> env) {
        Map<String, String> s = new LinkedHashMap<>();
        Set<String> secrets = new LinkedHashSet<>();
        if (!k.clientProperties().isBlank()) {
            Path file = Path.of(k.clientProperties());
            Properties p = new Properties();
            try (Reader r = Files.newBufferedReader(file, StandardCharsets.UTF_8)) {
                p.load(r);
            } catch (IOException | IllegalArgumentException e) {
                throw new InputException(file.toString(), 0, null, InputProblem.UNREADABLE,
                        "kafka.client_properties: could not read the Kafka client properties file: " + e.getMessage(), null);
            }
            for (String key : new TreeMap<>(p).keySet().stream().map(Object::toString).toList()) {
                String why = OWNED.get(key);
                if (why != null) {
                    throw new InputException(file.toString(), 0, key, InputProblem.INVALID_CONFIGURATION,
                            "'" + key + "' is set by trajeval-pipeline itself and cannot be changed here (" + why + ")", key);
                }
                String v = p.getProperty(key);
                s.put(key, v);
                if (SECRET_KEY.matcher(key).matches() && !v.contains("${")) {
                    secrets.add(v);
                }
            }
        }
        applyShortcuts(k.security(), env, s, secrets);
        return new ClientSettings(s, secrets);
    }

    private static void applyShortcuts(PipelineConfig.Security sec, Map<String, String> env, Map<String, String> s,
            Set<String> secrets) {
        if (sec == null) {
            return;
        }
        if (!sec.protocol().isBlank()) {
            String protocol = sec.protocol().trim().toUpperCase(Locale.ROOT);
            if (!PROTOCOLS.contains(protocol)) {
                throw bad("kafka.security.protocol", "must be one of PLAINTEXT, SSL, SASL_PLAINTEXT, SASL_SSL", sec.protocol());
            }
            s.put("security.protocol", protocol);
        }
        if (!sec.saslMechanism().isBlank()) {
            String mechanism = sec.saslMechanism().trim().toUpperCase(Locale.ROOT);
            String module = LOGIN_MODULES.get(mechanism);
            if (module == null) {
                throw bad("kafka.security.sasl_mechanism", "must be PLAIN, SCRAM-SHA-256 or SCRAM-SHA-512 (other "
                        + "mechanisms: use kafka.client_properties)", sec.saslMechanism());
            }
            String user = sec.saslUsername();
            if (user.isBlank() || user.indexOf('"') >= 0 || user.indexOf('\\') >= 0) {
                throw bad("kafka.security.sasl_username", "must be set, without quotes or backslashes", user);
            }
            String password = secret("kafka.security.sasl_password", sec.saslPassword(), env, true);
            secrets.add(password);
            s.put("sasl.mechanism", mechanism);
            s.put("sasl.jaas.config", module + " required username=\"" + user + "\" password=\""
                    + password.replace("\\", "\\\\").replace("\"", "\\\"") + "\";");
        }
        if (!sec.truststore().isBlank()) {
            s.put("ssl.truststore.location", existing("kafka.security.truststore", sec.truststore()));
            s.put("ssl.truststore.type", storeType(sec.truststore()));
            if (!sec.truststorePassword().isBlank()) {
                String pw = secret("kafka.security.truststore_password", sec.truststorePassword(), env, true);
                secrets.add(pw);
                s.put("ssl.truststore.password", pw);
            }
        }
        if (!sec.keystore().isBlank()) {
            s.put("ssl.keystore.location", existing("kafka.security.keystore", sec.keystore()));
            s.put("ssl.keystore.type", storeType(sec.keystore()));
            String pw = secret("kafka.security.keystore_password", sec.keystorePassword(), env, true);
            secrets.add(pw);
            s.put("ssl.keystore.password", pw);
            s.put("ssl.key.password", pw);
        }
    }

    private static String storeType(String file) {
        String f = file.toLowerCase(Locale.ROOT);
        return f.endsWith(".jks") ? "JKS" : f.endsWith(".pem") || f.endsWith(".crt") ? "PEM" : "PKCS12";
    }

    private static String existing(String key, String file) {
        if (!Files.isRegularFile(Path.of(file)) || !Files.isReadable(Path.of(file))) {
            throw bad(key, "must be a readable file", file);
        }
        return file;
    }

    /**
     * @return the secret a reference points at: {@code env:VAR} (the variable's value) or
     *     {@code file:PATH} (the file's content, one trailing newline dropped)
     * @throws InputException on a literal value (never echoed), an unset variable or an unreadable file
     */
    static String secret(String key, String reference, Map<String, String> env, boolean required) {
        if (reference.startsWith("env:")) {
            String var = reference.substring(4);
            String v = env.get(var);
            if (v == null || v.isEmpty()) {
                throw bad(key, "refers to the environment variable " + var + ", which is not set", reference);
            }
            return v;
        }
        if (reference.startsWith("file:")) {
            Path f = Path.of(reference.substring(5));
            try {
                String v = Files.readString(f, StandardCharsets.UTF_8);
                return v.endsWith("\r\n") ? v.substring(0, v.length() - 2) : v.endsWith("\n") ? v.substring(0, v.length() - 1) : v;
            } catch (IOException e) {
                throw bad(key, "refers to a file that cannot be read (" + e.getClass().getSimpleName() + ")", reference);
            }
        }
        if (reference.isBlank() && !required) {
            return "";
        }
        // the value is (probably) the secret itself: say so without echoing it
        throw new InputException("configuration", 0, key, InputProblem.INVALID_CONFIGURATION, key
                + " must be a reference, env:VARIABLE or file:PATH; a secret is never written in the configuration or "
                + "on the command line (it would show in shell history, ps and logs)", reference.isBlank() ? "nothing" : "a literal value");
    }

    private static InputException bad(String key, String expected, String found) {
        return new InputException("configuration", 0, key, InputProblem.INVALID_CONFIGURATION, key + " " + expected, found);
    }

    /** @return the settings with every secret masked ({@code ****}; a {@code ${provider:...}} reference is shown) */
    public Map<String, String> masked() {
        Map<String, String> m = new TreeMap<>();
        settings.forEach((k, v) -> m.put(k, mask(k, v)));
        return m;
    }

    private static String mask(String key, String value) {
        if (key.equals("sasl.jaas.config")) {
            return JAAS_PASSWORD.matcher(value).replaceAll(mr -> Matcher.quoteReplacement(
                    mr.group().contains("${") ? mr.group() : mr.group(1) + "\"****\""));
        }
        if (SECRET_KEY.matcher(key).matches() && !value.startsWith("${")) {
            return "****";
        }
        return value;
    }

    /** @return {@code text} with every known secret replaced by {@code ****} */
    public String scrub(String text) {
        String t = text;
        for (String secret : secrets) {
            if (secret.length() >= 4) {
                t = t.replace(secret, "****");
            }
        }
        return t;
    }
}
