package org.trajeval.pipeline.bundle;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.trajeval.pipeline.Fixtures;

/**
 * The plain run.yaml reader gives the YAML mapper's tree (node types and key order) whenever it takes a
 * file, and leaves every other file to the mapper. Reference: the service's YAML mapper itself.
 */
class PlainRunYamlTest {
    private static final ObjectMapper YAML = org.trajeval.core.io.StrictMappers.yaml();

    /** Values a run.yaml may hold: words, numbers, and the scalars YAML reads as something else. */
    private static final String[] VALUES = {"run-000000", "bot-0", "loop", "bench", "gt.tum", "est.csv", "a/b.csv",
        "orb_slam3", "V1.2", "x", "Z9", "e5", "E", "NaN", "nan", "Infinity", "inf", ".inf", ".nan", "yes", "Yes", "YES",
        "no", "No", "y", "Y", "n", "N", "on", "On", "ON", "off", "OFF", "true", "True", "TRUE", "false", "FALSE",
        "null", "Null", "NULL", "~", "0", "7", "20261123", "2147483647", "2147483648", "4294967296",
        "999999999999999999", "9999999999999999999", "010", "0x1F", "0o17", "1_000", "1e3", "1.5", ".5", "+1", "-1",
        "-0", "2.10", "12:30", "2026-11-25", "a b", "'quoted'", "\"quoted\"", "a#b", "a #c", "[1, 2]", "{a: 1}",
        "&anchor", "*alias", "!tag x", "|", ">", "%x", "@x", "`x", "a: b", "a\r", "", " lead", "trail "};
    private static final String[] KEYS = {"run_id", "robot_id", "sequence", "method", "seed", "reference",
        "estimate", "site", "software_version", "plot", "x1", "Upper", "1key", "with space", "", "_", "on", "yes", "null",
        "y", "true", "no_"};

    @Test
    void theBenchmarkAndFixtureManifestsAreTakenWithTheMappersTree() throws Exception {
        // the form every generated bundle has (bench/pipeline/GenerateBundles.java, Fixtures.manifest): the fast path
        // must take it, or the service quietly falls back to the YAML parser for every run
        for (String text : List.of(
                "run_id: run-000000\nrobot_id: bot-0\nsequence: loop\nmethod: bench\nseed: 20261123\n"
                        + "reference: gt.tum\nestimate: est.tum\n",
                Fixtures.manifest("r1", "bot-1", "gt.csv", "est.csv"),
                "run_id: r1\nreference: gt.csv\nestimate: est.csv")) {
            JsonNode plain = PlainRunYaml.read(text);
            assertNotNull(plain, text);
            assertSameTree(YAML.readTree(text), plain, text);
        }
    }

    @Test
    void everyLineOfKeyAndValueIsTheMappersOrLeftToIt() throws Exception {
        int taken = 0;
        for (String k : KEYS) {
            for (String v : VALUES) {
                String text = "run_id: r1\n" + k + ": " + v + "\n";
                taken += compare(text) ? 1 : 0;
            }
        }
        // words and plain numbers of the list above, under the keys that are lower-case words
        assertEquals(true, taken > 100, "taken: " + taken);
    }

    @Test
    void seededManifestsAreTheMappersOrLeftToIt() throws Exception {
        Random rnd = new Random(20261126L);
        String[] separators = {": ", ":", ":  ", " : ", ":\t"};
        String[] ends = {"\n", "\n", "\n", "\r\n", "\n\n", " #c\n", " \n"};
        for (int i = 0; i < 20_000; i++) {
            StringBuilder b = new StringBuilder();
            if (rnd.nextInt(50) == 0) {
                b.append(rnd.nextBoolean() ? "---\n" : "\uFEFF");
            }
            int lines = 1 + rnd.nextInt(8);
            for (int l = 0; l < lines; l++) {
                b.append(KEYS[rnd.nextInt(rnd.nextInt(4) == 0 ? KEYS.length : 10)]);
                b.append(rnd.nextInt(10) == 0 ? separators[rnd.nextInt(separators.length)] : ": ");
                b.append(VALUES[rnd.nextInt(rnd.nextInt(3) == 0 ? VALUES.length : 10)]);
                if (l < lines - 1 || rnd.nextBoolean()) {
                    b.append(rnd.nextInt(8) == 0 ? ends[rnd.nextInt(ends.length)] : "\n");
                }
            }
            compare(b.toString());
        }
    }

    @Test
    void repeatedKeysCommentsAndNestedMappingsAreLeftToTheMapper() {
        for (String text : new String[] {"run_id: a\nrun_id: b\n", "# comment\nrun_id: a\n", "run_id: a # c\n",
            "run_id: a\nmetrics:\n  alignment: se2\n", "run_id: a\n\nseed: 1\n", "run_id: 'a'\n", "", "\n",
            "run_id: a\r\nseed: 1\r\n", "  run_id: a\n", "run_id:  a\n"}) {
            assertNull(PlainRunYaml.read(text), text);
        }
    }

    @Test
    void seededCharacterSoupIsTheMappersOrLeftToIt() {
        // documents made character by character, with YAML's other line breaks (NEL, U+2028, U+2029), a BOM,
        // a no-break space, tabs, CR and indicator characters: whatever the plain reader takes, the mapper
        // reads the same
        String[] parts = {"a", "z", "k", "_", "0", "1", "9", ":", " ", "\n", "\n", "\r", "\t", "#", "'", "\"", "-",
            ".", "/", "Y", "e", "N", "\u0085", "\u2028", "\u2029", "\uFEFF", "\u00e9", "\u00a0", "x: ", "run_id: ",
            ": ", ": ", "y", "o", "n", "f", "t", "---", "...", "%", "!", "&", "*", "|", ">", "[", "{", "?", "~", "+",
            "0x"};
        Random rnd = new Random(20261126L);
        int taken = 0;
        for (int i = 0; i < 300_000; i++) {
            StringBuilder b = new StringBuilder();
            for (int j = 1 + rnd.nextInt(20); j > 0; j--) {
                b.append(parts[rnd.nextInt(parts.length)]);
            }
            taken += compare(b.toString()) ? 1 : 0;
        }
        assertEquals(true, taken > 50, "taken: " + taken);
    }

    @Test
    void aKeyPastYamlsLimitForASimpleKeyIsLeftToTheMapper() throws Exception {
        // YAML reads 'key: value' as a mapping only while the key has at most 1024 characters: a longer one made
        // the mapper give one text (first line) or refuse the file (later line), where the plain reader took it as
        // a key, so the run failed with "unknown key" instead of the mapper's message (found by rt9)
        for (int n : new int[] {1, 64, 65, 1024, 1025, 1100, 5000}) {
            for (String before : new String[] {"", "run_id: r1\n"}) {
                String text = before + "k".repeat(n) + ": v\n";
                try {
                    YAML.readTree(text);
                } catch (Exception refused) {
                    assertNull(PlainRunYaml.read(text), "the mapper refuses a key of " + n + " characters");
                    continue;
                }
                compare(text);
            }
        }
    }

    /** @return whether the plain reader took {@code text}; when it did, its tree must be the mapper's */
    private static boolean compare(String text) {
        JsonNode plain = PlainRunYaml.read(text);
        if (plain == null) {
            return false;
        }
        JsonNode mapped;
        try {
            mapped = YAML.readTree(text);
        } catch (Exception e) {
            throw new AssertionError("the mapper refuses what the plain reader took: " + text, e);
        }
        assertSameTree(mapped, plain, text);
        return true;
    }

    private static void assertSameTree(JsonNode expected, JsonNode actual, String text) {
        assertEquals(expected, actual, text); // node types compared too: IntNode(7) differs from LongNode(7)
        assertEquals(names(expected), names(actual), text);
        for (String k : names(expected)) {
            assertEquals(expected.get(k).getNodeType(), actual.get(k).getNodeType(), text);
            assertEquals(expected.get(k).numberType(), actual.get(k).numberType(), text);
            assertEquals(expected.get(k).getClass(), actual.get(k).getClass(), text);
        }
    }

    private static List<String> names(JsonNode n) {
        List<String> out = new ArrayList<>();
        n.fieldNames().forEachRemaining(out::add);
        return out;
    }
}
