package org.trajeval.core.io.bag;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import org.trajeval.core.InputException;
import org.trajeval.core.io.DuplicateTimestamps;
import org.trajeval.core.io.ReadOptions;

/**
 * A process that reads a trajectory from a bag the way {@code trajeval eval} does, for the tests
 * that start it in child JVMs: {@code BagStart BAG TOPIC [wait]}. It prints the number of poses
 * read and "read"; with {@code wait} it then waits for a line on stdin (or to be killed). A refused
 * bag prints the message on stderr and exits 2.
 */
final class BagStart {
    private BagStart() {
    }

    public static void main(String[] args) throws Exception {
        int poses;
        try {
            poses = BagTrajectoryReader.read(Path.of(args[0]), BagReadOptions.of(args[1]),
                    ReadOptions.defaults().withDuplicates(DuplicateTimestamps.KEEP)).trajectory().size();
        } catch (InputException e) {
            System.err.println(e.getMessage());
            System.exit(2);
            return;
        }
        System.out.println(poses);
        System.out.println("read");
        System.out.flush();
        if (args.length > 2 && "wait".equals(args[2])) {
            new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8)).readLine();
        }
    }
}
