package org.trajeval.core.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.core.traj.PlanarTrajectory;

/**
 * The byte path (in-place scanner, fastdoubleparser) and the Commons CSV path (JDK
 * Double.parseDouble) must give the same bits, which are those of Double.parseDouble (= numpy).
 */
class NumberParsingTest {
    private static final String[] SPECIAL = {
        "1e-300", "-0.0", "0.0", "123456789.123456789", "5e-324", "4.9e-324", "2.2250738585072014E-308",
        "2.2250738585072011e-308", "1.7976931348623157e308", "9007199254740993", "9007199254740992.5",
        "0.1", "+.5", "5.", "1E22", "1e23", "-1e-22", "1.7e-23", "0.30000000000000004", "3.141592653589793238462643",
        "00000000000000000000001.5", "1311868229.5760", "1.403715572212143183e+09", "1403715524907143168",
        "123456789012345678901234567890", "0.000000000000000000000000000001", "7.0E-10", "-2.5e+3"};

    private static String randomNumber(SplittableRandom rnd) {
        switch (rnd.nextInt(6)) {
            case 0:
                return SPECIAL[rnd.nextInt(SPECIAL.length)];
            case 1: // fixed decimals, as loggers write
                return String.format(Locale.ROOT, "%." + rnd.nextInt(10) + "f", rnd.nextDouble(-1e6, 1e6));
            case 2: // shortest repr of a random bit pattern
                double d;
                do {
                    d = Double.longBitsToDouble(rnd.nextLong());
                } while (!Double.isFinite(d));
                return Double.toString(d);
            case 3: { // many digits, random exponent
                StringBuilder sb = new StringBuilder(rnd.nextBoolean() ? "-" : "");
                int digits = 1 + rnd.nextInt(30);
                for (int i = 0; i < digits; i++) {
                    sb.append((char) ('0' + rnd.nextInt(10)));
                    if (i == 0 && rnd.nextBoolean()) {
                        sb.append('.');
                    }
                }
                sb.append(rnd.nextBoolean() ? 'e' : 'E').append(rnd.nextInt(-330, 310));
                return sb.toString();
            }
            case 4: // epoch stamps
                return String.format(Locale.ROOT, "%.9f", 1.3e9 + rnd.nextDouble(0, 5e8));
            default: // integers of every size
                return Long.toString(rnd.nextLong() >>> rnd.nextInt(64));
        }
    }

    @Test
    void scannerGivesTheBitsOfDoubleParseDouble() {
        SplittableRandom rnd = new SplittableRandom(20240611);
        DecimalScanner scanner = new DecimalScanner();
        for (int i = 0; i < 200_000; i++) {
            String s = randomNumber(rnd);
            byte[] b = (" " + s + ",").getBytes(StandardCharsets.US_ASCII);
            int end = scanner.scan(b, 1, b.length - 1);
            assertEquals(b.length - 1, end, s);
            assertEquals(Double.doubleToRawLongBits(Double.parseDouble(s)), Double.doubleToRawLongBits(scanner.value()), s);
        }
    }

    @Test
    void scannerInsideABigBufferGivesTheBitsOfDoubleParseDouble() {
        // the eight-bytes-at-a-time path needs 40 readable bytes: numbers in the middle of a long
        // line, followed by a delimiter, or by more digits past the field's end (which must not count)
        SplittableRandom rnd = new SplittableRandom(20261122);
        DecimalScanner scanner = new DecimalScanner();
        for (int i = 0; i < 200_000; i++) {
            String s = randomNumber(rnd);
            boolean digitsAfter = rnd.nextBoolean();
            String after = digitsAfter ? "9876543210987654321098765432109876543210" : ",1.5,2.5,3.5,4.5,5.5,6.5,7.5,8.5,9.5,10.5";
            byte[] b = ("12," + s + after).getBytes(StandardCharsets.US_ASCII);
            int to = 3 + s.length();
            int end = scanner.scan(b, 3, to);
            assertEquals(to, end, s);
            assertEquals(Double.doubleToRawLongBits(Double.parseDouble(s)), Double.doubleToRawLongBits(scanner.value()), s);
        }
    }

    @Test
    void scannerInsideABigBufferStopsAtTheFirstByteThatIsNotPartOfTheNumber() {
        DecimalScanner scanner = new DecimalScanner();
        String pad = ",0000000000000000000000000000000000000000";
        String[][] cases = {{"12.5x", "12.5"}, {"-0.25,", "-0.25"}, {"7.", "7."}, {"1e5", "1e5"}, {"1e", "1"},
            {"3.25e-2 ", "3.25e-2"}, {"-", ""}, {".", ""}, {"+.5;", "+.5"}, {"12345678901234567.5,", "12345678901234567.5"},
            {"0.1234567890123456789,", "0.1234567890123456789"}};
        for (String[] c : cases) {
            byte[] b = (c[0] + pad).getBytes(StandardCharsets.US_ASCII);
            int end = scanner.scan(b, 0, c[0].length());
            assertEquals(c[1].length(), end, c[0]);
            if (end > 0) {
                assertEquals(Double.parseDouble(c[1]), scanner.value(), c[0]);
            }
        }
    }

    @Test
    void syntaxIsNarrowerThanJavaAndPython() {
        for (String bad : new String[] {"", "-", "+", ".", "e5", ".e5", "1e", "1e+", "0x1p3", "1.0d", "1f", "NaN",
            "Infinity", "inf", "1_000", "1.2.3", "1,5", "--1", " 1"}) {
            assertFalse(DecimalText.isDecimal(bad), bad);
        }
        for (String good : SPECIAL) {
            assertTrue(DecimalText.isDecimal(good), good);
        }
    }

    @Test
    void fastPathAndCommonsCsvPathAgreeBitForBit(@TempDir Path dir) throws IOException {
        SplittableRandom rnd = new SplittableRandom(42);
        List<String> plain = new ArrayList<>();
        List<String> quoted = new ArrayList<>();
        plain.add("t,x,y,yaw,extra");
        quoted.add("\"t\",x,y,yaw,extra");
        double t = 0;
        for (int i = 0; i < 5000; i++) {
            t += 1e-3 + rnd.nextDouble();
            String ts = Double.toString(t);
            String x = randomNumber(rnd);
            String y = randomNumber(rnd);
            String yaw = randomNumber(rnd);
            if (!Double.isFinite(Double.parseDouble(x)) || !Double.isFinite(Double.parseDouble(y))
                    || !Double.isFinite(Double.parseDouble(yaw))
                    || Math.abs(Double.parseDouble(x)) > 1e9 || Math.abs(Double.parseDouble(y)) > 1e9) {
                continue; // positions beyond 1e9 m are refused (OUT_OF_RANGE); yaw keeps the extreme numbers
            }
            plain.add(ts + "," + x + ", " + y + " ," + yaw + ",note");
            quoted.add("\"" + ts + "\"," + x + ",\"" + y + "\"," + yaw + ",\"a, \"\"quoted\"\" note\"");
        }
        Path plainFile = Files.write(dir.resolve("plain.csv"), plain);
        Path quotedFile = Files.write(dir.resolve("quoted.csv"), quoted);
        ReadOptions options = ReadOptions.defaults();

        PlanarTrajectory fast = (PlanarTrajectory) CsvTrajectoryReader.readPlain(ByteSource.of(plainFile), "plain.csv", options, "given")
                .trajectory();
        PlanarTrajectory commons = (PlanarTrajectory) QuotedCsvReader.read(ByteSource.of(plainFile), "plain.csv", options, "given")
                .trajectory();
        PlanarTrajectory viaQuotes = (PlanarTrajectory) TrajectoryReader.read(quotedFile, options).trajectory();

        assertEquals(plain.size() - 1, fast.size());
        for (PlanarTrajectory other : List.of(commons, viaQuotes)) {
            assertEquals(fast.size(), other.size());
            for (int i = 0; i < fast.size(); i++) {
                assertBits(fast.t(i), other.t(i));
                assertBits(fast.x(i), other.x(i));
                assertBits(fast.y(i), other.y(i));
                assertBits(fast.yaw(i), other.yaw(i));
            }
        }
        // and both are Double.parseDouble of the text
        for (int i = 0; i < fast.size(); i++) {
            String[] f = plain.get(i + 1).split(",");
            assertBits(Double.parseDouble(f[1].trim()), fast.x(i));
            assertBits(Double.parseDouble(f[3].trim()), fast.yaw(i));
        }
    }

    @Test
    void quotedFileHashIsTheFileHash(@TempDir Path dir) throws IOException {
        Path file = Files.writeString(dir.resolve("q.csv"), "\"t\",\"x\",\"y\",\"yaw\"\n0,\"1.5\",2,3\n");
        assertEquals(RefdataReadingTest.sha256(file), TrajectoryReader.read(file, ReadOptions.defaults()).sha256());
    }

    private static void assertBits(double expected, double actual) {
        assertEquals(Double.doubleToRawLongBits(expected), Double.doubleToRawLongBits(actual),
                expected + " vs " + actual);
    }
}
