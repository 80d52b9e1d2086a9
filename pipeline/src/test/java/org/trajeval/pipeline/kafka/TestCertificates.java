package org.trajeval.pipeline.kafka;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * Certificates for the secured-broker tests, made with the JDK's {@code keytool}: a CA, the
 * broker's key and certificate (SAN IP:127.0.0.1, DNS:localhost) signed by it, a client's for
 * mutual TLS, and a truststore holding the CA. Every store is PKCS12 with its own password.
 *
 * @param dir where the files are
 * @param truststore the CA, for clients and for the broker's mTLS listener
 * @param brokerKeystore the broker's key and certificate chain
 * @param clientKeystore the client's key and certificate chain (CN=trajeval-client)
 * @param password the stores' password (one generated per test run)
 */
record TestCertificates(Path dir, Path truststore, Path brokerKeystore, Path clientKeystore, String password) {

    /** Generates everything in {@code dir}. */
    static TestCertificates generate(Path dir, String password) throws IOException, InterruptedException {
        Files.createDirectories(dir);
        Path ca = dir.resolve("ca.p12");
        Path caPem = dir.resolve("ca.pem");
        Path trust = dir.resolve("truststore.p12");
        keytool("-genkeypair", "-alias", "ca", "-keyalg", "RSA", "-keysize", "2048", "-dname", "CN=trajeval-test-ca",
                "-ext", "bc:c", "-validity", "2", "-keystore", ca.toString(), "-storepass", password, "-storetype", "PKCS12");
        keytool("-exportcert", "-rfc", "-alias", "ca", "-keystore", ca.toString(), "-storepass", password,
                "-file", caPem.toString());
        keytool("-importcert", "-noprompt", "-alias", "ca", "-file", caPem.toString(), "-keystore", trust.toString(),
                "-storepass", password, "-storetype", "PKCS12");
        Path broker = signed(dir, ca, caPem, "broker", "CN=127.0.0.1", "SAN=IP:127.0.0.1,DNS:localhost", password);
        Path client = signed(dir, ca, caPem, "client", "CN=trajeval-client", null, password);
        return new TestCertificates(dir, trust, broker, client, password);
    }

    private static Path signed(Path dir, Path ca, Path caPem, String name, String dname, String san, String password)
            throws IOException, InterruptedException {
        Path ks = dir.resolve(name + ".p12");
        Path csr = dir.resolve(name + ".csr");
        Path pem = dir.resolve(name + ".pem");
        List<String> gen = new ArrayList<>(List.of("-genkeypair", "-alias", name, "-keyalg", "RSA", "-keysize", "2048",
                "-dname", dname, "-validity", "2", "-keystore", ks.toString(), "-storepass", password, "-storetype", "PKCS12"));
        List<String> sign = new ArrayList<>(List.of("-gencert", "-rfc", "-alias", "ca", "-keystore", ca.toString(),
                "-storepass", password, "-infile", csr.toString(), "-outfile", pem.toString(), "-validity", "2"));
        if (san != null) {
            gen.addAll(List.of("-ext", san));
            sign.addAll(List.of("-ext", san));
        }
        keytool(gen.toArray(String[]::new));
        keytool("-certreq", "-alias", name, "-keystore", ks.toString(), "-storepass", password, "-file", csr.toString());
        keytool(sign.toArray(String[]::new));
        keytool("-importcert", "-noprompt", "-alias", "ca", "-file", caPem.toString(), "-keystore", ks.toString(),
                "-storepass", password);
        keytool("-importcert", "-noprompt", "-alias", name, "-file", pem.toString(), "-keystore", ks.toString(),
                "-storepass", password);
        return ks;
    }

    private static void keytool(String... args) throws IOException, InterruptedException {
        List<String> cmd = new ArrayList<>();
        cmd.add(Path.of(System.getProperty("java.home"), "bin", "keytool").toString());
        cmd.addAll(List.of(args));
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        String out = new String(p.getInputStream().readAllBytes());
        if (!p.waitFor(60, TimeUnit.SECONDS) || p.exitValue() != 0) {
            throw new IllegalStateException("keytool " + args[0] + " failed: " + out);
        }
    }
}
