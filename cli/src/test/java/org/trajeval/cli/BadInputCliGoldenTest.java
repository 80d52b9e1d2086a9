package org.trajeval.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HexFormat;
import java.util.List;
import java.util.Map;
import java.util.TreeSet;
import java.util.stream.Stream;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.TestFactory;
import org.junit.jupiter.api.io.TempDir;

/**
 * Golden bad inputs of the command line, one folder per case under {@code cli/src/test/resources/bad-input/}:
 * {@code args} (one argument a line, {@code {dir}} is the case's working copy), {@code exit} (the exit code),
 * {@code stderr} and optionally {@code stdout} (exact text, {@code {dir}} for the working copy), the input
 * files, and optionally {@code setup} (lines {@code fifo NAME}, {@code symlink LINK TARGET},
 * {@code hardlink LINK TARGET}, {@code hex NAME BYTES}, {@code utf16le NAME SOURCE}, {@code raw NAME TEXT}
 * with C escapes such as {@code \e}, {@code \a}, {@code \n}). A new case's {@code stderr}, {@code stdout} and
 * {@code exit} are written by a run with {@code -Dgolden.record=true}, to be read and checked by hand. Besides the golden text, every case checks
 * that no input was changed and, when refused, that nothing was written. A case must end within 60 s: a
 * FIFO must not hang the command. Adding a case is adding a folder.
 */
class BadInputCliGoldenTest {
    private static final String[] CONTROL = {"args", "exit", "stderr", "stdout", "setup"};

    @TempDir
    Path work;

    static Path casesDir() {
        return Path.of(System.getProperty("trajeval.projectDir", "."), "src", "test", "resources", "bad-input");
    }

    @TestFactory
    Stream<DynamicTest> everyBadInputGetsItsGoldenRefusal() throws IOException {
        List<Path> cases;
        try (Stream<Path> s = Files.list(casesDir())) {
            cases = s.filter(Files::isDirectory).sorted().toList();
        }
        assertTrue(cases.size() >= 25, "cases found in " + casesDir() + ": " + cases.size());
        return cases.stream().map(c -> DynamicTest.dynamicTest(c.getFileName().toString(), () -> check(c)));
    }

    private void check(Path golden) throws Exception {
        Path dir = work.resolve(golden.getFileName().toString());
        Files.createDirectories(dir);
        try (Stream<Path> s = Files.list(golden)) {
            for (Path f : s.toList()) {
                if (!List.of(CONTROL).contains(f.getFileName().toString())) {
                    Files.copy(f, dir.resolve(f.getFileName().toString()));
                }
            }
        }
        setUp(golden.resolve("setup"), dir);
        Map<String, byte[]> before = snapshot(dir);
        List<String> args = new ArrayList<>();
        for (String a : Files.readAllLines(golden.resolve("args"), StandardCharsets.UTF_8)) {
            args.add(unescape(a.replace("{dir}", dir.toString())));
        }
        CliRun r = assertTimeoutPreemptively(Duration.ofSeconds(60),
                () -> CliRun.of(args.toArray(new String[0])));
        String err = r.err().replace(dir.toString(), "{dir}");
        String out = r.out().replace(dir.toString(), "{dir}");
        if (!Files.exists(golden.resolve("stderr")) && Boolean.getBoolean("golden.record")) {
            // writing a new case's golden text: review it by hand before committing
            Files.writeString(golden.resolve("stderr"), err);
            Files.writeString(golden.resolve("exit"), r.code() + "\n");
            if (!out.isEmpty()) {
                Files.writeString(golden.resolve("stdout"), out);
            }
        }
        assertEquals(Files.readString(golden.resolve("stderr")), err, "stderr");
        Path stdout = golden.resolve("stdout");
        assertEquals(Files.exists(stdout) ? Files.readString(stdout) : "", out, "stdout");
        assertEquals(Integer.parseInt(Files.readString(golden.resolve("exit")).trim()), r.code(), err);
        Map<String, byte[]> after = snapshot(dir);
        for (Map.Entry<String, byte[]> e : before.entrySet()) {
            assertTrue(after.containsKey(e.getKey()), "input removed: " + e.getKey());
            assertArrayEquals(e.getValue(), after.get(e.getKey()), "input changed: " + e.getKey());
        }
        if (r.code() != 0) {
            assertEquals(new TreeSet<>(before.keySet()), new TreeSet<>(after.keySet()), "files written on refusal");
        }
        assertFalse(err.chars().anyMatch(c -> c < 0x20 && c != '\n'), "control byte on stderr: " + err);
    }

    /** Regular files by name with their bytes (FIFOs and links are listed without reading them). */
    private static Map<String, byte[]> snapshot(Path dir) throws IOException {
        Map<String, byte[]> m = new HashMap<>();
        try (Stream<Path> s = Files.walk(dir)) {
            for (Path p : s.toList()) {
                String name = dir.relativize(p).toString();
                if (Files.isRegularFile(p, LinkOption.NOFOLLOW_LINKS)) {
                    m.put(name, Files.readAllBytes(p));
                } else if (!p.equals(dir)) {
                    m.put(name, new byte[0]);
                }
            }
        }
        return m;
    }

    private static void setUp(Path setup, Path dir) throws IOException, InterruptedException {
        if (!Files.exists(setup)) {
            return;
        }
        for (String line : Files.readAllLines(setup, StandardCharsets.UTF_8)) {
            String[] w = line.trim().split(" ", 3);
            if (w.length < 2) {
                continue;
            }
            Path p = dir.resolve(w[1]);
            switch (w[0]) {
                case "fifo" -> assertEquals(0, new ProcessBuilder("mkfifo", p.toString()).start().waitFor());
                case "symlink" -> Files.createSymbolicLink(p, Path.of(w[2]));
                case "hardlink" -> Files.createLink(p, dir.resolve(w[2]));
                case "hex" -> Files.write(p, HexFormat.of().parseHex(w[2].replace(" ", "")));
                case "raw" -> Files.writeString(p, unescape(w[2]), StandardCharsets.UTF_8);
                case "utf16le" -> {
                    byte[] text = Files.readString(dir.resolve(w[2])).getBytes(StandardCharsets.UTF_16LE);
                    byte[] bom = {(byte) 0xff, (byte) 0xfe};
                    byte[] all = new byte[bom.length + text.length];
                    System.arraycopy(bom, 0, all, 0, 2);
                    System.arraycopy(text, 0, all, 2, text.length);
                    Files.write(p, all);
                }
                default -> throw new IllegalArgumentException("unknown setup line: " + line);
            }
        }
    }

    /** C escapes {@code \e \a \n \t \\} as in the args and setup files. */
    static String unescape(String s) {
        StringBuilder sb = new StringBuilder();
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            if (c != '\\' || i + 1 == s.length()) {
                sb.append(c);
                continue;
            }
            char n = s.charAt(++i);
            sb.append(switch (n) {
                case 'e' -> '\u001b';
                case 'a' -> '\u0007';
                case 'n' -> '\n';
                case 't' -> '\t';
                default -> n;
            });
        }
        return sb.toString();
    }
}
