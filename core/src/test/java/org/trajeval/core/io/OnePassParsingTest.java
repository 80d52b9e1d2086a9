package org.trajeval.core.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.core.InputException;

/**
 * The one-pass line parser ({@link NumericRows#next}: fields split, numbers scanned and the line end
 * found in one pass over the buffer) against a reading written here by hand from the documented
 * rules: lines end at '\n' (one '\r' before it dropped), blank lines and lines whose first non-blank
 * byte is '#' are skipped, fields are split on runs of spaces and tabs or on the delimiter (each
 * trimmed of spaces and tabs), and every selected field must match the number syntax and be finite,
 * its value that of {@link Double#parseDouble}. Inputs are seeded random numbers of every form and
 * seeded mutations of them (CRLF, stray '\r', comments, quotes, missing last newline).
 */
class OnePassParsingTest {
    /** The accepted number syntax, written independently of {@link DecimalText}. */
    private static final Pattern NUMBER = Pattern.compile("[+-]?([0-9]+(\\.[0-9]*)?|\\.[0-9]+)([eE][+-]?[0-9]+)?");
    private static final String MUTATIONS = "0123456789.,;-+eE \t\r\n#\"x";

    /** A number in one of the forms files hold: signs, leading zeros, 1-25 digits, point, exponent. */
    static String randomNumber(SplittableRandom rnd) {
        StringBuilder sb = new StringBuilder();
        int sign = rnd.nextInt(4);
        if (sign == 0) {
            sb.append('-');
        } else if (sign == 1) {
            sb.append('+');
        }
        for (int z = rnd.nextInt(4) == 0 ? rnd.nextInt(4) : 0; z > 0; z--) {
            sb.append('0');
        }
        // 17-19 significant digits are the edge of the exact path: drawn often
        int intDigits = rnd.nextInt(3) == 0 ? rnd.nextInt(26) : rnd.nextInt(12);
        int fracDigits = rnd.nextInt(3) == 0 ? 17 + rnd.nextInt(3) - Math.min(intDigits, 17) : rnd.nextInt(26);
        boolean point = rnd.nextInt(5) != 0 || intDigits == 0;
        if (intDigits == 0 && (!point || fracDigits == 0)) {
            intDigits = 1;
        }
        for (int i = 0; i < intDigits; i++) {
            sb.append((char) ('0' + rnd.nextInt(i == 0 && intDigits > 1 ? 1 : 0, 10)));
        }
        if (point) {
            sb.append('.');
            for (int i = 0; i < fracDigits; i++) {
                sb.append((char) ('0' + rnd.nextInt(10)));
            }
        }
        if (rnd.nextInt(6) == 0) {
            sb.append(rnd.nextBoolean() ? 'e' : 'E');
            int s = rnd.nextInt(3);
            sb.append(s == 0 ? "-" : s == 1 ? "+" : "");
            sb.append(rnd.nextInt(0, 330));
        }
        return sb.toString();
    }

    /** As {@link #randomNumber}, but never one that overflows (which would end the file's reading there). */
    static String finiteNumber(SplittableRandom rnd) {
        String s = randomNumber(rnd);
        while (Double.isInfinite(Double.parseDouble(s))) {
            s = randomNumber(rnd);
        }
        return s;
    }

    @Test
    void scannerGivesTheBitsOfDoubleParseDoubleForEveryFormAndWindow() {
        SplittableRandom rnd = new SplittableRandom(20261125);
        DecimalScanner scanner = new DecimalScanner();
        String[] after = {"", ",", " ", "\n", "\r\n", "9", "123456789012345678901234567890123456789012345", ".5", "e5", "x"};
        for (int i = 0; i < 300_000; i++) {
            String s = randomNumber(rnd);
            assertTrue(NUMBER.matcher(s).matches(), s);
            String prefix = "1,".repeat(rnd.nextInt(3));
            // the suffix decides whether the scanner has its 40-byte window or is near the buffer's end
            String suffix = after[rnd.nextInt(after.length)];
            suffix = suffix.substring(0, rnd.nextInt(suffix.length() + 1));
            byte[] b = (prefix + s + suffix).getBytes(StandardCharsets.US_ASCII);
            int from = prefix.length();
            int to = from + s.length();
            assertEquals(to, scanner.scan(b, from, to), s + suffix);
            assertEquals(Double.doubleToRawLongBits(Double.parseDouble(s)), Double.doubleToRawLongBits(scanner.value()),
                    s);
        }
    }

    @Test
    void scannerTakesANumberOnlyWhenAFieldEndFollowsAndThenGivesTheBitsOfDoubleParseDouble() {
        // the line parser's call: the number must be followed by one of the field's end bytes, checked
        // in the scanner's own words; anything else is left to the general scan (LONG_NUMBER)
        SplittableRandom rnd = new SplittableRandom(20261126);
        DecimalScanner scanner = new DecimalScanner();
        long ends = DecimalScanner.byteSet(' ', '\t', '\n', '\r', ',');
        String followers = " \t\n\r,;x#.e5-";
        int taken = 0;
        for (int i = 0; i < 300_000; i++) {
            String s = randomNumber(rnd);
            char after = followers.charAt(rnd.nextInt(followers.length()));
            String text = s + after + "1234567890123456789012345678901234567890";
            byte[] b = text.getBytes(StandardCharsets.US_ASCII);
            int end = scanner.scanShort(b, 0, b.length, ends);
            boolean fieldEnd = " \t\n\r,".indexOf(after) >= 0;
            if (end == DecimalScanner.LONG_NUMBER) {
                continue; // left to the general scan: always allowed
            }
            taken++;
            assertTrue(fieldEnd, text);
            assertEquals(s.length(), end, text);
            assertEquals(Double.doubleToRawLongBits(Double.parseDouble(s)), Double.doubleToRawLongBits(scanner.value()),
                    text);
        }
        assertTrue(taken > 30_000, "the short path took only " + taken); // not vacuous: 55 326 with this seed
    }

    @Test
    void scannerReadsPointInFirstWordLongFractionsAndShortExponentsExactly() {
        // the forms of the bench, TUM, KITTI and EuRoC files, and the edges of each of the scanner's words
        String[] numbers = {"1000.003000", "-8.807629", "27.022919", "0.138780483402", "-0.000081368405", "5.", ".5",
            "-.5", "+7", "0", "-0.0", "1305031102.175304", "1403715273262142976", "1.000000e+00", "9.043680e-12",
            "-2.326809E-11", "5.551115e-17", "1e22", "1e-22", "3e23", "1.5e308", "0.1234567890123456", "0.12345678901234567",
            "1.23456789012345678", "12.3456789012345678", "1234567.12345678901", "0.000000000000000001e5",
            "9007199254740993", "900719925474099.3", "1234567.1", "12345678.12345678", "9.99999999999999999e2"};
        DecimalScanner scanner = new DecimalScanner();
        long ends = DecimalScanner.byteSet(' ', '\n');
        for (String s : numbers) {
            for (String after : new String[] {" ", "\n"}) {
                byte[] b = (s + after + "9".repeat(40)).getBytes(StandardCharsets.US_ASCII);
                int end = scanner.scanShort(b, 0, b.length, ends);
                if (end == DecimalScanner.LONG_NUMBER) {
                    end = scanner.scan(b, 0, s.length());
                }
                assertEquals(s.length(), end, s);
                assertEquals(Double.doubleToRawLongBits(Double.parseDouble(s)),
                        Double.doubleToRawLongBits(scanner.value()), s);
            }
        }
    }

    @Test
    void validTumLinesReadAsSplitByHandAcrossBlocksWithCrlfAndNoLastNewline(@TempDir Path dir) throws IOException {
        // more than two 1 MiB blocks: lines are cut at block ends and the buffer is compacted
        SplittableRandom rnd = new SplittableRandom(7);
        StringBuilder sb = new StringBuilder();
        while (sb.length() < 2_500_000) {
            if (rnd.nextInt(50) == 0) {
                sb.append(rnd.nextBoolean() ? "# comment 1 2 3" : " \t");
            } else {
                sb.append(rnd.nextInt(10) == 0 ? " " : "");
                for (int f = 0; f < 8; f++) {
                    sb.append(f == 0 ? "" : rnd.nextInt(10) == 0 ? " \t " : " ").append(randomNumber(rnd));
                }
                sb.append(rnd.nextInt(10) == 0 ? "\t" : "");
            }
            sb.append(rnd.nextInt(8) == 0 ? "\r\n" : "\n");
        }
        sb.append("1 2 3 4 5 6 7 8"); // last line without a newline
        checkAgainstHand(dir, sb.toString(), NumericRows.WHITESPACE, 8, new int[] {0, 1, 2, 3, 4, 5, 6, 7});
    }

    @Test
    void validCsvLinesWithUnselectedColumnsReadAsSplitByHand(@TempDir Path dir) throws IOException {
        SplittableRandom rnd = new SplittableRandom(8);
        StringBuilder sb = new StringBuilder();
        while (sb.length() < 1_500_000) {
            for (int f = 0; f < 6; f++) {
                String field = f == 2 ? "name " + rnd.nextInt(100) : randomNumber(rnd);
                sb.append(f == 0 ? "" : ",").append(rnd.nextInt(10) == 0 ? " " : "").append(field)
                        .append(rnd.nextInt(10) == 0 ? "\t" : "");
            }
            sb.append(rnd.nextInt(8) == 0 ? "\r\n" : "\n");
        }
        checkAgainstHand(dir, sb.toString(), (byte) ',', 6, new int[] {0, 1, 4, 5});
    }

    @Test
    void csvLinesWhoseSelectedColumnsComeFirstReadAsSplitByHand(@TempDir Path dir) throws IOException {
        // EuRoC's layout: the selected fields first, then unselected ones (here text, blanks, CRLF)
        SplittableRandom rnd = new SplittableRandom(10);
        StringBuilder sb = new StringBuilder();
        while (sb.length() < 1_500_000) {
            for (int f = 0; f < 7; f++) {
                String field = f == 5 ? "name " + rnd.nextInt(100) : finiteNumber(rnd);
                sb.append(f == 0 ? "" : ";").append(rnd.nextInt(10) == 0 ? " " : "").append(field)
                        .append(rnd.nextInt(10) == 0 ? "\t" : "");
            }
            sb.append(rnd.nextInt(8) == 0 ? "\r\n" : "\n");
        }
        checkAgainstHand(dir, sb.toString(), (byte) ';', 7, new int[] {0, 1, 2, 3});
        checkAgainstHand(dir, sb.toString(), (byte) ';', 7, new int[] {0, 1, 2, 3, 4});
    }

    @Test
    void mutatedLinesAreReadOrRefusedAtTheLineTheRulesRefuse(@TempDir Path dir) throws IOException {
        SplittableRandom rnd = new SplittableRandom(9);
        for (int file = 0; file < 1500; file++) {
            boolean csv = rnd.nextBoolean();
            // a blank delimiter is also a blank to trim: the one-pass parser must not take it as a mere separator
            char d = csv ? ",,; \t".charAt(rnd.nextInt(5)) : ' ';
            StringBuilder sb = new StringBuilder();
            int lines = 1 + rnd.nextInt(12);
            for (int l = 0; l < lines; l++) {
                StringBuilder line = new StringBuilder();
                for (int f = 0; f < 4; f++) {
                    line.append(f == 0 ? "" : String.valueOf(d)).append(rnd.nextInt(4) == 0 ? "12.5" : randomNumber(rnd));
                }
                for (int m = rnd.nextInt(3) == 0 ? 1 + rnd.nextInt(2) : 0; m > 0; m--) {
                    int at = rnd.nextInt(line.length() + 1);
                    char c = MUTATIONS.charAt(rnd.nextInt(MUTATIONS.length()));
                    if (rnd.nextBoolean() && at < line.length()) {
                        line.setCharAt(at, c);
                    } else {
                        line.insert(at, c);
                    }
                }
                int kind = rnd.nextInt(10);
                if (kind == 0) {
                    line.insert(0, rnd.nextBoolean() ? "#" : " \t#"); // a comment that is a row of numbers after its '#'
                } else if (kind == 1) {
                    line.setLength(0);
                    line.append(rnd.nextBoolean() ? "" : " \t"); // a blank line
                }
                sb.append(line).append(rnd.nextInt(4) == 0 ? "\r\n" : "\n");
            }
            String text = rnd.nextInt(4) == 0 ? sb.substring(0, sb.length() - 1) : sb.toString();
            // a first field left unselected lets a comment or blank line look like a row of numbers
            boolean skipFirst = rnd.nextBoolean();
            // and the one-pass parser has a path of its own for selected fields that come first
            int kind2 = rnd.nextInt(3);
            int[] select = skipFirst ? new int[] {1, 2, 3} : !csv || kind2 == 0 ? new int[] {0, 1, 2, 3}
                    : kind2 == 1 ? new int[] {0, 1} : new int[] {0, 1, 3};
            checkAgainstHand(dir, text, csv ? (byte) d : NumericRows.WHITESPACE, 4, select);
        }
    }

    /** Reads {@code text} with {@link NumericRows} and compares with {@link #byHand}. */
    private static void checkAgainstHand(Path dir, String text, byte delimiter, int fields, int[] select)
            throws IOException {
        Path file = dir.resolve("f.txt");
        Files.writeString(file, text, StandardCharsets.ISO_8859_1);
        Hand expected = byHand(text, delimiter, fields, select);
        List<double[]> rows = new ArrayList<>();
        Long refused = null;
        boolean quoted = false;
        try (ByteLines lines = ByteLines.open(file, "f.txt", Long.MAX_VALUE)) {
            NumericRows r = new NumericRows(lines, "f.txt", delimiter, delimiter != NumericRows.WHITESPACE);
            String[] names = new String[select.length];
            java.util.Arrays.fill(names, "c");
            r.select(select, names, names);
            r.requireFields(fields, "test");
            double[] row = new double[select.length];
            while (r.next(row)) {
                rows.add(row.clone());
            }
        } catch (InputException e) {
            refused = e.line();
        } catch (NeedsQuotedCsv e) {
            quoted = true;
        }
        String where = "in\n" + text.replace("\r", "\\r");
        assertEquals(expected.quoted, quoted, where);
        if (!quoted) {
            assertEquals(expected.refusedLine, refused, where);
            assertEquals(expected.rows.size(), rows.size(), where);
            for (int i = 0; i < rows.size(); i++) {
                for (int k = 0; k < select.length; k++) {
                    assertEquals(Double.doubleToRawLongBits(expected.rows.get(i)[k]),
                            Double.doubleToRawLongBits(rows.get(i)[k]), "row " + i + " " + where);
                }
            }
        }
    }

    /** The rows the rules give, up to the first refused line (its 1-based number), or a quote seen. */
    private record Hand(List<double[]> rows, Long refusedLine, boolean quoted) {
    }

    private static Hand byHand(String text, byte delimiter, int fields, int[] select) {
        List<double[]> rows = new ArrayList<>();
        String[] lines = text.split("\n", -1);
        int count = text.endsWith("\n") ? lines.length - 1 : lines.length;
        for (int l = 0; l < count; l++) {
            String line = lines[l].endsWith("\r") ? lines[l].substring(0, lines[l].length() - 1) : lines[l];
            String blankless = line.replaceFirst("^[ \t]+", "");
            if (blankless.isEmpty() || blankless.startsWith("#")) {
                continue;
            }
            String[] f;
            if (delimiter == NumericRows.WHITESPACE) {
                f = blankless.replaceFirst("[ \t]+$", "").split("[ \t]+");
            } else {
                if (line.indexOf('"') >= 0) {
                    return new Hand(rows, null, true);
                }
                f = line.split(Pattern.quote(String.valueOf((char) delimiter)), -1);
                for (int i = 0; i < f.length; i++) {
                    f[i] = f[i].replaceFirst("^[ \t]+", "").replaceFirst("[ \t]+$", "");
                }
            }
            if (f.length != fields) {
                return new Hand(rows, (long) l + 1, false);
            }
            double[] row = new double[select.length];
            for (int k = 0; k < select.length; k++) {
                String s = f[select[k]];
                if (!NUMBER.matcher(s).matches() || Double.isInfinite(Double.parseDouble(s))) {
                    return new Hand(rows, (long) l + 1, false);
                }
                row[k] = Double.parseDouble(s);
            }
            rows.add(row);
        }
        assertNotNull(rows);
        return new Hand(rows, null, false);
    }

    @Test
    void handReadingRefusesWhatItShould() {
        // the reference itself: a wrong count, a bad number and an overflow are refused at their line
        assertEquals(2L, byHand("1 2\n1 2 3\n", NumericRows.WHITESPACE, 2, new int[] {0, 1}).refusedLine());
        assertEquals(1L, byHand("1,2x\n", (byte) ',', 2, new int[] {0, 1}).refusedLine());
        assertEquals(1L, byHand("1e999 2\n", NumericRows.WHITESPACE, 2, new int[] {0, 1}).refusedLine());
        assertEquals(1, byHand("# c\n\r\n 1\t2 \r\n", NumericRows.WHITESPACE, 2, new int[] {0, 1}).rows().size());
        if (byHand("1,\"2\"\n", (byte) ',', 2, new int[] {0, 1}).quoted()) {
            return;
        }
        fail("a quote in a CSV line needs the quoted reader");
    }
}
