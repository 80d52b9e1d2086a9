package org.trajeval.spark;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.apache.hadoop.conf.Configuration;
import org.apache.hadoop.fs.FileSystem;
import org.apache.hadoop.hdfs.MiniDFSCluster;
import org.apache.spark.sql.Row;
import org.apache.spark.sql.RowFactory;
import org.apache.spark.sql.SparkSession;
import org.apache.spark.sql.types.DataTypes;
import org.apache.spark.sql.types.StructType;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.core.protocol.RunMetric;

/**
 * Pairs on a real HDFS (a NameNode and a DataNode of Hadoop's MiniDFSCluster in this JVM, on
 * 127.0.0.1 with free ports, blocks in a temporary folder) scored in local[2]: every statistic bit
 * for bit and the whole report byte for byte as the same files from the local disk, apart from the
 * file names (the URI as written); a missing file and a folder are failed rows naming the URI.
 */
class HdfsPairsTest {
    private static final String[][] PAIRS = {
        {"freiburg1_xyz-groundtruth.txt", "freiburg1_xyz-rgbdslam.txt", null, null},
        {"freiburg1_xyz-groundtruth.txt", "freiburg1_xyz-ORB_kf_mono.txt", "evo", "sim3"},
        {"V102_groundtruth.csv", "V102.txt", "evo", "se3"},
        {"KITTI_00_gt.txt", "KITTI_00_ORB.txt", "kitti", null},
    };
    private static final StructType SCHEMA = new StructType()
            .add("ref", DataTypes.StringType).add("est", DataTypes.StringType).add("run", DataTypes.StringType)
            .add("convention", DataTypes.StringType).add("alignment", DataTypes.StringType);

    @TempDir
    static Path tmp;
    private static MiniDFSCluster dfs;
    private static SparkSession spark;
    private static String hdfs;

    @BeforeAll
    static void start() throws Exception {
        Configuration conf = new Configuration();
        conf.set(MiniDFSCluster.HDFS_MINIDFS_BASEDIR, tmp.resolve("dfs").toString());
        conf.set("dfs.namenode.http-address", "127.0.0.1:0");
        conf.set("dfs.namenode.https-address", "127.0.0.1:0");
        dfs = new MiniDFSCluster.Builder(conf, tmp.resolve("dfs").toFile()).numDataNodes(1).build();
        dfs.waitActive();
        FileSystem fs = dfs.getFileSystem();
        for (String[] p : PAIRS) {
            for (int k = 0; k < 2; k++) {
                fs.copyFromLocalFile(new org.apache.hadoop.fs.Path(local(p[k])),
                        new org.apache.hadoop.fs.Path("/fleet/" + p[k]));
            }
        }
        fs.mkdirs(new org.apache.hadoop.fs.Path("/fleet/a-folder.txt"));
        hdfs = "hdfs://127.0.0.1:" + dfs.getNameNodePort() + "/fleet/";
        spark = LocalSpark.start();
    }

    @AfterAll
    static void stop() {
        if (spark != null) {
            spark.stop();
        }
        if (dfs != null) {
            dfs.shutdown();
        }
    }

    private static String local(String name) {
        return LocalSpark.refdata().resolve(name).toAbsolutePath().toString();
    }

    @Test
    void pairsOnHdfsScoreBitForBitAsTheSameFilesOnTheLocalDisk() {
        List<Row> rows = new ArrayList<>();
        for (int i = 0; i < PAIRS.length; i++) {
            String[] p = PAIRS[i];
            rows.add(RowFactory.create(local(p[0]), local(p[1]), "local-" + i, p[2], p[3]));
            rows.add(RowFactory.create(hdfs + p[0], hdfs + p[1], "hdfs-" + i, p[2], p[3]));
        }
        rows.add(RowFactory.create(hdfs + PAIRS[0][0], hdfs + "no-such-file.txt", "missing", null, null));
        rows.add(RowFactory.create(hdfs + PAIRS[0][0], hdfs + "a-folder.txt", "folder", null, null));
        List<Row> out = TrajevalSpark.score(spark.createDataFrame(rows, SCHEMA).repartition(2), Map.of())
                .collectAsList();

        assertEquals(rows.size(), out.size(), "one row per pair");
        Map<String, Row> byRun = new HashMap<>();
        out.forEach(r -> byRun.put(r.getAs("run"), r));
        for (int i = 0; i < PAIRS.length; i++) {
            Row a = byRun.get("local-" + i);
            Row b = byRun.get("hdfs-" + i);
            assertEquals(ResultSchema.OK, a.getAs(ResultSchema.STATUS), "local " + i + ": " + a.getAs(ResultSchema.FAILURE_DETAIL));
            assertEquals(ResultSchema.OK, b.getAs(ResultSchema.STATUS), "hdfs " + i + ": " + b.getAs(ResultSchema.FAILURE_DETAIL));
            for (RunMetric m : RunMetric.values()) {
                Double x = a.getAs(m.key());
                Double y = b.getAs(m.key());
                assertEquals(x == null ? null : Double.doubleToLongBits(x), y == null ? null : Double.doubleToLongBits(y),
                        PAIRS[i][1] + " " + m.key());
            }
            for (String c : List.of(ResultSchema.MATCHED, ResultSchema.DROPPED)) {
                assertEquals(a.<Integer>getAs(c), b.<Integer>getAs(c), c);
            }
            String localReport = a.getAs(ResultSchema.REPORT);
            String hdfsReport = b.getAs(ResultSchema.REPORT);
            // the same report, input hashes included; the file fields name the URI as written
            assertTrue(hdfsReport.contains("\"" + hdfs + PAIRS[i][1] + "\""), hdfsReport);
            String dir = LocalSpark.refdata().toAbsolutePath() + "/";
            assertEquals(localReport, hdfsReport.replace(hdfs, dir), PAIRS[i][1] + ": report");
        }
        Row missing = byRun.get("missing");
        assertEquals(ResultSchema.FAILED, missing.getAs(ResultSchema.STATUS));
        assertEquals("unreadable", missing.getAs(ResultSchema.FAILURE_REASON));
        assertEquals(hdfs + "no-such-file.txt: the file does not exist", missing.getAs(ResultSchema.FAILURE_DETAIL));
        Row folder = byRun.get("folder");
        assertEquals("unreadable", folder.getAs(ResultSchema.FAILURE_REASON));
        assertEquals(hdfs + "a-folder.txt: this is a directory, not a file", folder.getAs(ResultSchema.FAILURE_DETAIL));
    }
}
