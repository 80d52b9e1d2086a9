package org.trajeval.bench;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.io.ReadOptions;
import org.trajeval.core.io.bag.BagIntegrity;
import org.trajeval.core.io.bag.BagLimits;
import org.trajeval.core.io.bag.BagReadOptions;
import org.trajeval.core.io.bag.StampSource;
import org.trajeval.core.io.bag.BagTrajectoryReader;

/**
 * Reading one pose topic out of a generated MCAP bag that also holds unrelated high-rate topics
 * ({@link BenchBag}: a 200 kB "image" and a 100 kB "point cloud" every {@code heavyEvery} poses,
 * in chunks of their own, so that only the pose chunks need to be read): {@code poses}
 * geometry_msgs/PoseStamped messages in chunks of 1000, uncompressed or lz4. The bag is written
 * once into {@code bench/data/bags/} (git-ignored; about 1.7 GB for the defaults). Score: ms per
 * read of the whole topic; poses per second = poses / score * 1000. {@code bench/bag-throughput.sh}
 * runs it under {@code nice} and prints the best iteration with the load average.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.SingleShotTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Fork(value = 1, jvmArgsAppend = {"-Xmx2g"})
@Warmup(iterations = 2)
@Measurement(iterations = 5)
public class BagBenchmarks {
    @Param({"1000000"})
    public int poses;

    /** Poses between two heavy messages (an image and a point cloud). */
    @Param({"200"})
    public int heavyEvery;

    @Param({"none", "lz4"})
    public String compression;

    /** bag_crc: all (the data section CRC pass over the whole file too) or chunks (the chunks read only). */
    @Param({"all", "chunks"})
    public String bagCrc;

    private Path bag;
    private BagReadOptions options;

    @Setup
    public void writeBag() throws IOException {
        Path dir = Path.of(System.getProperty("bench.data", "data"), "bags");
        Files.createDirectories(dir);
        bag = BenchBag.write(dir.resolve("poses-" + poses + "-heavy" + heavyEvery + "-" + compression + ".mcap"),
                poses, heavyEvery, compression.equals("none") ? "" : compression);
        options = new BagReadOptions("/pose", StampSource.HEADER, null, BagLimits.DEFAULT,
                BagIntegrity.valueOf(bagCrc.toUpperCase(java.util.Locale.ROOT)));
    }

    @Benchmark
    public int readPoseTopic() {
        LoadedTrajectory t = BagTrajectoryReader.read(bag, options, ReadOptions.defaults());
        return t.trajectory().size();
    }
}
