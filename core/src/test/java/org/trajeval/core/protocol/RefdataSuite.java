package org.trajeval.core.protocol;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;

/**
 * A small suite on the real reference data (evo's TUM files in ../shared/refdata): two sequences
 * (fr1_xyz, fr2_desk), two methods, one seed, Sim(3) alignment (the ORB files are monocular). The
 * manifest may only name files inside its folder, so the files are copied into {@code dir} (a
 * temporary folder of the test, never the project). Method {@code rgbdslam} has no estimate of
 * fr2_desk: that run fails as {@code missing_estimate}.
 */
public final class RefdataSuite {
    /** The manifest's file name. */
    public static final String MANIFEST = "suite.yaml";

    private static final String YAML = """
            format: trajeval.suite-manifest
            version: 1
            name: refdata-tum
            seeds: [1]
            sequences:
              - {id: fr1_xyz, session: fr1, reference: gt/fr1_xyz.txt, split: test, tags: [indoor]}
              - {id: fr2_desk, session: fr2, reference: gt/fr2_desk.txt, split: test, tags: [indoor]}
            methods:
              - {name: orb, estimates: "runs/orb/{sequence}.txt"}
              - {name: rgbdslam, estimates: "runs/rgbdslam/{sequence}.txt"}
            metrics:
              convention: evo
              alignment: sim3
              rpe: {delta: 1.0, unit: s, pairs: consecutive}
            score:
              - {metric: ate_trans_rmse_m, cap: 0.5, weight: 0.5}
              - {metric: rpe_trans_rmse_m, cap: 0.5, weight: 0.5}
            budget: {device: cpu, real_time_factor: 1.0, memory_cap_mib: 4096}
            """;

    private RefdataSuite() {
    }

    /**
     * @param dir the suite's folder (created)
     * @param refdata the reference data folder
     * @return the manifest
     */
    public static Path write(Path dir, Path refdata) {
        String[][] files = {
            {"freiburg1_xyz-groundtruth.txt", "gt/fr1_xyz.txt"},
            {"fr2_desk_groundtruth.txt", "gt/fr2_desk.txt"},
            {"freiburg1_xyz-ORB_kf_mono.txt", "runs/orb/fr1_xyz.txt"},
            {"fr2_desk_ORB.txt", "runs/orb/fr2_desk.txt"},
            {"freiburg1_xyz-rgbdslam.txt", "runs/rgbdslam/fr1_xyz.txt"},
        };
        try {
            for (String[] f : files) {
                Path to = dir.resolve(f[1]);
                Files.createDirectories(to.getParent());
                Files.copy(refdata.resolve(f[0]), to, StandardCopyOption.REPLACE_EXISTING);
            }
            Path manifest = dir.resolve(MANIFEST);
            Files.writeString(manifest, YAML);
            return manifest;
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
