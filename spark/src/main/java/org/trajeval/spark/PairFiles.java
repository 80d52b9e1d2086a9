package org.trajeval.spark;

import java.io.IOException;
import java.io.Serializable;
import java.net.URI;
import java.net.URISyntaxException;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.Map;
import org.apache.hadoop.conf.Configuration;
import org.apache.hadoop.fs.FileSystem;
import org.apache.hadoop.fs.LocalFileSystem;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;

/**
 * Where the trajectory named in a pairs table lives, resolved through the Hadoop FileSystem API
 * with the job's Hadoop configuration: a plain path or a {@code file:} URI is a file on the
 * executor's own disk (Hadoop's local file system), read in place by trajeval's readers. Other
 * file systems ({@code hdfs:}, {@code s3a:}, ...) are refused per pair in this version (see the
 * README, "On Spark"): trajeval's readers take a file and read it twice (format, then data).
 * Serializable: the driver's Hadoop settings travel to the executors as text.
 */
final class PairFiles implements Serializable {
    private static final long serialVersionUID = 1L;

    private final HashMap<String, String> hadoopSettings;
    private transient Configuration conf;

    PairFiles(Configuration driverConf) {
        this.hadoopSettings = new HashMap<>();
        for (Map.Entry<String, String> e : driverConf) {
            hadoopSettings.put(e.getKey(), e.getValue());
        }
    }

    /**
     * @param text the path or URI as written in the table
     * @param column the column it came from (for refusals)
     * @return the local file
     * @throws InputException (UNREADABLE) on an empty value, a malformed URI or a file system that is not local
     */
    Path resolve(String text, String column) {
        if (text == null || text.isBlank()) {
            throw new InputException(null, 0, column, InputProblem.UNREADABLE,
                    "column '" + column + "' must name a trajectory file (a path or a Hadoop URI), found none", text);
        }
        URI uri;
        try {
            uri = new URI(text);
        } catch (URISyntaxException e) {
            // a local path with characters a URI does not allow (spaces, ...)
            return Path.of(text);
        }
        if (uri.getScheme() == null || uri.getScheme().length() == 1) {
            return Path.of(text); // a plain path (or a Windows drive letter)
        }
        try {
            FileSystem fs = FileSystem.get(uri, configuration());
            if (fs instanceof LocalFileSystem local) {
                return local.pathToFile(new org.apache.hadoop.fs.Path(uri)).toPath();
            }
            throw new InputException(text, 0, column, InputProblem.UNREADABLE, "file system '" + uri.getScheme()
                    + "' is not read by this version of trajeval-spark (local paths and file: URIs are); copy the "
                    + "files to the executors' disks or a mounted folder", uri.getScheme());
        } catch (IOException e) {
            throw new InputException(text, 0, column, InputProblem.UNREADABLE, "cannot open its file system: "
                    + e.getMessage(), text, e);
        }
    }

    private Configuration configuration() {
        if (conf == null) {
            Configuration c = new Configuration(false);
            hadoopSettings.forEach(c::set);
            conf = c;
        }
        return conf;
    }
}
