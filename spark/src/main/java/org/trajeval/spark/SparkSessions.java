package org.trajeval.spark;

import org.apache.spark.SparkConf;
import org.apache.spark.sql.SparkSession;

/**
 * The Spark session of the job: the master given ({@code --master}), else the one spark-submit
 * set, else {@value #DEFAULT_MASTER}. In local mode the driver binds and advertises the loopback
 * address only ({@code spark.driver.host}, {@code spark.driver.bindAddress}; with
 * {@code SPARK_LOCAL_IP=127.0.0.1}, which the launcher sets, nothing listens elsewhere).
 */
final class SparkSessions {
    /** The master when none is given: every core of this machine. */
    static final String DEFAULT_MASTER = "local[*]";
    /** The loopback address. */
    static final String LOOPBACK = "127.0.0.1";

    private SparkSessions() {
    }

    /**
     * @param master the master URL, or {@code null} for spark-submit's or the default
     * @param appName the application's name
     * @return the session (created, or the one already running in this JVM)
     */
    static SparkSession open(String master, String appName) {
        SparkConf conf = new SparkConf();
        if (master != null) {
            conf.setMaster(master);
        } else if (!conf.contains("spark.master")) {
            conf.setMaster(DEFAULT_MASTER);
        }
        if (conf.get("spark.master").startsWith("local")) {
            conf.setIfMissing("spark.driver.host", LOOPBACK);
            conf.setIfMissing("spark.driver.bindAddress", LOOPBACK);
            conf.setIfMissing("spark.ui.enabled", "false");
        }
        conf.setIfMissing("spark.ui.showConsoleProgress", "false");
        conf.setAppName(appName);
        return SparkSession.builder().config(conf).getOrCreate();
    }
}
