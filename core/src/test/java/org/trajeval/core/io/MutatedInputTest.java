package org.trajeval.core.io;

import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.core.InputException;

/** Seeded mutations of valid files of every format: the only exception a reader may throw is InputException. */
class MutatedInputTest {
    private static final String[] SEEDS = {
        "t,x,y,yaw\n0.0,1.0,2.0,0.1\n0.1,1.1,2.1,0.2\n0.2,1.2,2.2,0.3\n",
        "\"t\",x,y,yaw\n0.0,\"1.0\",2.0,0.1\n0.1,1.1,2.1,0.2\n",
        "# c\n1311868164.3 0.1 0.2 0.3 0 0 0 1\n1311868164.4 0.1 0.2 0.3 0 0 0.7071068 0.7071068\n",
        "1 0 0 0.1 0 1 0 0.2 0 0 1 0.3\n0 -1 0 1 1 0 0 2 0 0 1 3\n",
        "#timestamp, p_x, p_y, p_z, q_w, q_x, q_y, q_z\n1403715524907143168,0.5,2.0,0.9,1.0,0.0,0.0,0.0\n"
                + "1403715524912143104,0.5,2.0,0.9,0.0,1.0,0.0,0.0\n",
    };
    private static final byte[] ALPHABET = "0123456789.,;-+eE \t\n\r#\"xnaif\u0000\u00ff".getBytes(StandardCharsets.ISO_8859_1);

    @Test
    void mutatedFilesAreReadOrRefusedWithAnInputException(@TempDir Path dir) throws IOException {
        SplittableRandom rnd = new SplittableRandom(1234);
        Path file = dir.resolve("m.txt");
        Path csv = dir.resolve("m.csv");
        Path times = Files.writeString(dir.resolve("times.txt"), "0.0\n0.5\n1.0\n");
        TrajectoryFormat[] formats = {null, TrajectoryFormat.CSV, TrajectoryFormat.TUM, TrajectoryFormat.KITTI,
            TrajectoryFormat.EUROC};
        for (int i = 0; i < 4000; i++) {
            byte[] b = SEEDS[rnd.nextInt(SEEDS.length)].getBytes(StandardCharsets.ISO_8859_1);
            int edits = 1 + rnd.nextInt(4);
            for (int k = 0; k < edits; k++) {
                b = mutate(b, rnd);
            }
            Path target = rnd.nextBoolean() ? file : csv;
            Files.write(target, b);
            ReadOptions options = ReadOptions.defaults().withFormat(formats[rnd.nextInt(formats.length)])
                    .withOrder(rnd.nextBoolean() ? TimestampOrder.SORT : TimestampOrder.REFUSE_UNSORTED);
            if (rnd.nextInt(4) == 0) {
                options = options.withKittiTimes(times);
            }
            try {
                TrajectoryReader.read(target, options);
            } catch (InputException expected) {
                // a refusal is fine
            } catch (RuntimeException e) {
                fail("mutation " + i + " " + options.format() + " of\n" + new String(b, StandardCharsets.ISO_8859_1)
                        + "\nthrew " + e, e);
            }
        }
    }

    private static byte[] mutate(byte[] b, SplittableRandom rnd) {
        int at = b.length == 0 ? 0 : rnd.nextInt(b.length);
        byte c = ALPHABET[rnd.nextInt(ALPHABET.length)];
        switch (rnd.nextInt(3)) {
            case 0: { // replace
                if (b.length == 0) {
                    return new byte[] {c};
                }
                byte[] out = b.clone();
                out[at] = c;
                return out;
            }
            case 1: { // insert
                byte[] out = new byte[b.length + 1];
                System.arraycopy(b, 0, out, 0, at);
                out[at] = c;
                System.arraycopy(b, at, out, at + 1, b.length - at);
                return out;
            }
            default: { // delete
                if (b.length == 0) {
                    return b;
                }
                byte[] out = new byte[b.length - 1];
                System.arraycopy(b, 0, out, 0, at);
                System.arraycopy(b, at + 1, out, at, b.length - at - 1);
                return out;
            }
        }
    }
}
