package org.trajeval.e2e;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.security.MessageDigest;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.HexFormat;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Properties;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import java.util.zip.ZipEntry;
import java.util.zip.ZipInputStream;
import javax.xml.parsers.DocumentBuilderFactory;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.core.Version;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.NodeList;

/**
 * The examples of examples/ run as written, as their users run them, and the library published
 * as a user publishes it. One Gradle run of this checkout ({@code :core:publishToMavenLocal
 * :core:publish}, shared by the tests that need it) publishes trajeval-core into a temporary
 * local Maven repository ({@code -Dmaven.repo.local}) and over HTTP to a Maven repository this
 * test serves on 127.0.0.1 ({@link MavenRepositoryServer}); the ETL program is then built as a
 * separate Gradle build against that local repository, and the shell example runs with nothing
 * but the executable jar. Their numbers must be trajeval eval's, to the bit.
 */
class ExamplesTest {
    private static final long BUILD_TIMEOUT_S = 300;
    private static final long RUN_TIMEOUT_S = 120;
    private static final String USER = "ci";
    private static final String PASSWORD = "s3cret-" + Long.toHexString(System.nanoTime());
    // a documentation host (RFC 2606): the test checks that the -P values reach the POM
    private static final String SCM_URL = "https://git.example.org/robotics/trajeval";
    private static final String CORE = "org/trajeval/trajeval-core/";

    record Result(int code, String out, String err) {
    }

    /** What the shared Gradle run published: the local repository, the files uploaded over HTTP, the run. */
    record Publication(Path localRepo, Map<String, byte[]> uploaded, Map<String, Integer> unauthorised, Result gradle) {
    }

    @TempDir
    static Path shared;

    private static Publication publication;

    /** Publishes trajeval-core once (see the class comment); @return what was published */
    private static synchronized Publication publication() throws IOException, InterruptedException {
        if (publication == null) {
            Path checkout = required("trajeval.examples").getParent();
            Path localRepo = Files.createDirectories(shared.resolve("m2-repository"));
            try (MavenRepositoryServer server = MavenRepositoryServer.start(USER, PASSWORD)) {
                Result r = run(checkout, Map.of("TRAJEVAL_MAVEN_URL", server.url(), "TRAJEVAL_MAVEN_USERNAME", USER,
                        "TRAJEVAL_MAVEN_PASSWORD", PASSWORD), BUILD_TIMEOUT_S, "gradle", "--no-daemon", "--offline", "-q",
                        "-Dmaven.repo.local=" + localRepo, "-Ppom.url=" + SCM_URL, "-Ppom.scm.url=" + SCM_URL,
                        "-Ppom.scm.connection=scm:git:" + SCM_URL + ".git", ":core:publishToMavenLocal", ":core:publish");
                publication = new Publication(localRepo, server.files(), server.unauthorised(), r);
            }
        }
        assertEquals(0, publication.gradle().code(), "gradle publishToMavenLocal publish failed:\n"
                + publication.gradle().out() + publication.gradle().err());
        return publication;
    }

    @Test
    void etlExampleBuiltAgainstThePublishedLibraryWritesTrajevalEvalsReports(@TempDir Path tmp) throws Exception {
        Path examples = required("trajeval.examples");
        Path repo = publication().localRepo();
        Path refdata = required("trajeval.refdata");
        Properties props = new Properties();
        try (InputStream in = Files.newInputStream(examples.resolve("etl-java/gradle.properties"))) {
            props.load(in);
        }
        assertEquals(Version.TOOL, props.getProperty("trajevalVersion"),
                "examples/etl-java/gradle.properties must build against this release");
        assertTrue(Files.isRegularFile(repo.resolve("org/trajeval/trajeval-core/" + Version.TOOL + "/trajeval-core-"
                + Version.TOOL + ".pom")), "publishToMavenLocal put trajeval-core in -Dmaven.repo.local " + repo);

        Path project = copyTree(examples.resolve("etl-java"), tmp.resolve("etl"));
        Result build = run(project, Map.of(), BUILD_TIMEOUT_S, "gradle", "--no-daemon", "--offline", "-q",
                "-Dmaven.repo.local=" + repo, "installDist");
        assertEquals(0, build.code(), "consumer build failed:\n" + build.out() + build.err());

        Pairs pairs = pairs(tmp, refdata);
        Path out = tmp.resolve("reports");
        Result etl = run(tmp, Map.of(), RUN_TIMEOUT_S,
                project.resolve("build/install/score-pairs/bin/score-pairs").toString(), pairs.table().toString(),
                out.toString());
        assertEquals(2, etl.code(), "one pair is refused: exit 2\n" + etl.err());

        Map<String, String[]> summary = new HashMap<>();
        List<String> lines = Files.readAllLines(out.resolve("summary.csv"));
        assertEquals("name,status,ate_trans_rmse_m,ate_rot_rmse_rad,rpe_trans_rmse_m,rpe_rot_rmse_rad,matched,message",
                lines.get(0));
        for (String line : lines.subList(1, lines.size())) {
            summary.put(line.split(",", 2)[0], line.split(",", 8));
        }
        ObjectMapper json = new ObjectMapper();
        for (String[] pair : pairs.scored()) {
            String cli = evalJson(tmp, pair);
            assertEquals(cli, Files.readString(out.resolve(pair[0] + ".json")).trim(),
                    pair[0] + ": the example's report is trajeval eval's");
            JsonNode r = json.readTree(cli);
            String[] row = summary.get(pair[0]);
            assertEquals("scored", row[1]);
            assertEquals(r.at("/ate/trans_m/rmse").asDouble(), Double.parseDouble(row[2]), 0.0, pair[0]);
            assertEquals(r.at("/ate/rot_rad/rmse").asDouble(), Double.parseDouble(row[3]), 0.0, pair[0]);
            assertEquals(r.at("/rpe/trans_m/rmse").asDouble(), Double.parseDouble(row[4]), 0.0, pair[0]);
            assertEquals(r.at("/rpe/rot_rad/rmse").asDouble(), Double.parseDouble(row[5]), 0.0, pair[0]);
            assertEquals(r.at("/association/matched").asInt(), Integer.parseInt(row[6]), pair[0]);
        }
        String[] refused = summary.get("broken");
        assertEquals("refused", refused[1]);
        assertTrue(refused[7].contains("bad.csv:3: column 'yaw'"), refused[7]);
        assertTrue(Files.notExists(out.resolve("broken.json")), "no report for a refused pair");
    }

    @Test
    void publishPutsJarPomSourcesJavadocAndChecksumsOnAnHttpMavenRepository() throws Exception {
        Publication p = publication();
        assertEquals(Map.of(), p.unauthorised(), "every request carries the credentials from the environment");
        Map<String, byte[]> up = p.uploaded();
        String base = CORE + Version.TOOL + "/trajeval-core-" + Version.TOOL;
        for (String suffix : List.of(".jar", "-sources.jar", "-javadoc.jar", ".pom")) {
            byte[] file = up.get(base + suffix);
            assertTrue(file != null && file.length > 0, base + suffix + " uploaded; found " + up.keySet());
            assertChecksums(up, base + suffix);
            // the same reproducible bytes as publishToMavenLocal put in the local repository
            assertTrue(Arrays.equals(Files.readAllBytes(p.localRepo().resolve(base + suffix)), file),
                    base + suffix + ": the uploaded file equals the local publication's");
        }
        String metadata = new String(up.get(CORE + "maven-metadata.xml"), StandardCharsets.UTF_8);
        assertTrue(metadata.contains("<version>" + Version.TOOL + "</version>"), metadata);
        assertChecksums(up, CORE + "maven-metadata.xml");
        assertTrue(entries(up.get(base + "-sources.jar")).contains("org/trajeval/api/TrajectoryEvaluator.java"));
        assertTrue(entries(up.get(base + "-javadoc.jar")).contains("org/trajeval/api/TrajectoryEvaluator.html"));

        Document pom = DocumentBuilderFactory.newInstance().newDocumentBuilder()
                .parse(new ByteArrayInputStream(up.get(base + ".pom")));
        Map<String, String> scopes = new HashMap<>();
        NodeList deps = pom.getElementsByTagName("dependency");
        for (int i = 0; i < deps.getLength(); i++) {
            Element d = (Element) deps.item(i);
            scopes.put(text(d, "groupId") + ":" + text(d, "artifactId"), text(d, "scope"));
        }
        // core's signatures use Jackson (api): compile scope; the libraries behind core (implementation): runtime
        assertEquals("compile", scopes.get("com.fasterxml.jackson.core:jackson-databind"), scopes.toString());
        assertEquals("runtime", scopes.get("org.ejml:ejml-ddense"), scopes.toString());
        assertEquals("runtime", scopes.get("org.apache.commons:commons-math3"), scopes.toString());
        assertEquals("Apache License, Version 2.0", text(pom.getDocumentElement(), "name", "license"));
        assertEquals(SCM_URL, text(pom.getDocumentElement(), "url", "scm"));
    }

    private static void assertChecksums(Map<String, byte[]> up, String path) throws Exception {
        byte[] file = up.get(path);
        for (String[] kind : List.of(new String[] {"sha1", "SHA-1"}, new String[] {"md5", "MD5"})) {
            byte[] sum = up.get(path + "." + kind[0]);
            assertTrue(sum != null, path + "." + kind[0] + " uploaded");
            assertEquals(HexFormat.of().formatHex(MessageDigest.getInstance(kind[1]).digest(file)),
                    new String(sum, StandardCharsets.US_ASCII).trim(), path + "." + kind[0]);
        }
    }

    private static List<String> entries(byte[] jar) throws IOException {
        List<String> names = new ArrayList<>();
        try (ZipInputStream z = new ZipInputStream(new ByteArrayInputStream(jar))) {
            for (ZipEntry e = z.getNextEntry(); e != null; e = z.getNextEntry()) {
                names.add(e.getName());
            }
        }
        return names;
    }

    /** @return the text of the first {@code tag} element under {@code e} (inside {@code within}, when given), or null */
    private static String text(Element e, String tag, String... within) {
        Element scope = e;
        for (String w : within) {
            scope = (Element) scope.getElementsByTagName(w).item(0);
        }
        NodeList n = scope.getElementsByTagName(tag);
        return n.getLength() == 0 ? null : n.item(0).getTextContent().trim();
    }

    @Test
    void javaJarFromAFolderHoldingOnlyTheJarPrintsWhatTheLauncherPrints(@TempDir Path tmp) throws Exception {
        Path jar = required("trajeval.allJar");
        Path refdata = required("trajeval.refdata");
        Path alone = Files.createDirectory(tmp.resolve("alone"));
        Path copy = Files.copy(jar, alone.resolve(jar.getFileName()));
        String ref = refdata.resolve("freiburg1_xyz-groundtruth.txt").toString();
        String est = refdata.resolve("freiburg1_xyz-rgbdslam.txt").toString();

        Result viaJar = run(alone, Map.of(), RUN_TIMEOUT_S, "java", "-jar", copy.getFileName().toString(), "eval",
                ref, est);
        Result viaLauncher = run(tmp, Map.of(), RUN_TIMEOUT_S, launcher(), "eval", ref, est);
        assertEquals(0, viaJar.code(), viaJar.err());
        assertEquals("", viaJar.err());
        assertEquals(viaLauncher.out(), viaJar.out());

        Result version = run(alone, Map.of(), RUN_TIMEOUT_S, "java", "-jar", copy.toString(), "--version");
        assertEquals("trajeval " + Version.TOOL, version.out().trim());

        Result bad = run(alone, Map.of(), RUN_TIMEOUT_S, "java", "-jar", copy.toString(), "eval", ref,
                alone.resolve("missing.txt").toString());
        assertEquals(2, bad.code(), "bad input: exit 2");
        assertEquals(1, bad.err().lines().count(), bad.err());
    }

    @Test
    void shellExampleScoresEachPairWithTheJarAndSetsAsideRefusedOnes(@TempDir Path tmp) throws Exception {
        Path jar = required("trajeval.allJar");
        Path script = required("trajeval.examples").resolve("java-jar/score.sh");
        Pairs pairs = pairs(tmp, required("trajeval.refdata"));
        Path out = tmp.resolve("reports");
        Result r = run(tmp, Map.of("TRAJEVAL_JAR", jar.toString()), RUN_TIMEOUT_S * 4, "bash", script.toString(),
                pairs.table().toString(), out.toString());
        assertEquals(2, r.code(), "a refused pair: exit 2\n" + r.err());
        for (String[] pair : pairs.scored()) {
            assertEquals(evalJson(tmp, pair), Files.readString(out.resolve(pair[0] + ".json")).trim(), pair[0]);
        }
        String rejected = Files.readString(out.resolve("rejected.txt"));
        assertEquals(1, rejected.lines().count(), rejected);
        assertTrue(rejected.startsWith("broken: trajeval: ") && rejected.contains("bad.csv:3"), rejected);
    }

    /** A table of pairs: two real TUM pairs, a seeded planar CSV pair, and one with a bad file. */
    private static Pairs pairs(Path tmp, Path refdata) throws IOException {
        Path gt = refdata.resolve("freiburg1_xyz-groundtruth.txt");
        Path ref = tmp.resolve("planar-ref.csv");
        Path est = tmp.resolve("planar-est.csv");
        StringBuilder r = new StringBuilder("t,x,y,yaw\n");
        StringBuilder e = new StringBuilder("t,x,y,yaw\n");
        java.util.Random rnd = new java.util.Random(21);
        for (int i = 0; i < 500; i++) {
            double t = 10.0 + 0.1 * i;
            double x = 0.4 * i * Math.cos(0.003 * i);
            double y = 0.4 * i * Math.sin(0.003 * i);
            double yaw = 0.2 * Math.sin(0.02 * i);
            r.append(String.format(Locale.ROOT, "%.2f,%.6f,%.6f,%.6f%n", t, x, y, yaw));
            e.append(String.format(Locale.ROOT, "%.3f,%.6f,%.6f,%.6f%n", t + 0.004, x + 2 + 0.05 * rnd.nextGaussian(),
                    y - 1 + 0.05 * rnd.nextGaussian(), yaw + 0.1));
        }
        Files.writeString(ref, r);
        Files.writeString(est, e);
        Path bad = Files.writeString(tmp.resolve("bad.csv"), "t,x,y,yaw\n0.0,0,0,0\n0.1,0,0,nan\n");
        List<String[]> scored = List.of(
                new String[] {"fr1_rgbdslam", gt.toString(), refdata.resolve("freiburg1_xyz-rgbdslam.txt").toString()},
                new String[] {"fr1_orb_kf", gt.toString(), refdata.resolve("freiburg1_xyz-ORB_kf_mono.txt").toString()},
                new String[] {"planar", ref.getFileName().toString(), est.getFileName().toString()});
        StringBuilder table = new StringBuilder("name,reference,estimate\n");
        for (String[] p : scored) {
            table.append(String.join(",", p)).append('\n');
        }
        table.append("broken,planar-ref.csv,bad.csv\n");
        Path file = Files.writeString(tmp.resolve("pairs.csv"), table);
        // what trajeval eval is given for the same pairs: the table's relative paths from its folder
        List<String[]> resolved = new ArrayList<>();
        for (String[] p : scored) {
            resolved.add(new String[] {p[0], tmp.resolve(p[1]).toString(), tmp.resolve(p[2]).toString()});
        }
        return new Pairs(file, resolved);
    }

    record Pairs(Path table, List<String[]> scored) {
    }

    private static Path required(String property) {
        String value = System.getProperty(property);
        assertTrue(value != null && Files.exists(Paths.get(value)),
                "-D" + property + " must name an existing path (set by the root build.gradle), found " + value);
        return Paths.get(value);
    }

    /** Outputs of the installed launcher by arguments: the tests share its runs on the same pairs. */
    private static final Map<List<String>, String> EVAL_JSON = new java.util.concurrent.ConcurrentHashMap<>();

    /** trajeval eval REF EST --json by the installed launcher (table paths resolved from the table's folder). */
    private static String evalJson(Path tmp, String[] pair) throws IOException, InterruptedException {
        // the report names the paths: the same paths give the same report (files are not rewritten)
        List<String> key = List.of(pair[1], pair[2]);
        String cached = EVAL_JSON.get(key);
        if (cached != null) {
            return cached;
        }
        Result cli = run(tmp, Map.of(), RUN_TIMEOUT_S, launcher(), "eval", pair[1], pair[2], "--json");
        assertEquals(0, cli.code(), cli.err());
        EVAL_JSON.put(key, cli.out().trim());
        return cli.out().trim();
    }

    private static String launcher() {
        return required("trajeval.launcher").toString();
    }

    private static Path copyTree(Path from, Path to) throws IOException {
        try (Stream<Path> files = Files.walk(from)) {
            for (Path f : (Iterable<Path>) files::iterator) {
                Path rel = from.relativize(f);
                String top = rel.getNameCount() == 0 ? "" : rel.getName(0).toString();
                if (top.equals("build") || top.equals(".gradle")) {
                    continue;
                }
                Path target = to.resolve(rel.toString());
                if (Files.isDirectory(f)) {
                    Files.createDirectories(target);
                } else {
                    Files.copy(f, target);
                }
            }
        }
        return to;
    }

    private static Result run(Path dir, Map<String, String> env, long timeoutS, String... cmd)
            throws IOException, InterruptedException {
        Path out = Files.createTempFile("example-out", ".txt");
        Path err = Files.createTempFile("example-err", ".txt");
        try {
            ProcessBuilder pb = new ProcessBuilder(cmd).directory(dir.toFile()).redirectOutput(out.toFile())
                    .redirectError(err.toFile());
            pb.environment().putAll(env);
            Process p = pb.start();
            if (!p.waitFor(timeoutS, TimeUnit.SECONDS)) {
                p.destroyForcibly();
                throw new AssertionError(String.join(" ", cmd) + " did not finish in " + timeoutS + " s");
            }
            return new Result(p.exitValue(), Files.readString(out, StandardCharsets.UTF_8),
                    Files.readString(err, StandardCharsets.UTF_8));
        } finally {
            Files.deleteIfExists(out);
            Files.deleteIfExists(err);
        }
    }
}
