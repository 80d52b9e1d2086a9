package org.trajeval.spark;

import java.io.IOException;
import java.io.Serializable;
import java.net.URI;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.Map;
import java.util.regex.Pattern;
import org.apache.hadoop.conf.Configuration;
import org.apache.hadoop.fs.FileStatus;
import org.apache.hadoop.fs.FileSystem;
import org.apache.hadoop.fs.UnsupportedFileSystemException;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.io.InputBytes;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.io.ReadOptions;
import org.trajeval.core.io.TrajectoryFiles;
import org.trajeval.core.io.TrajectoryReader;

/**
 * Reads the trajectories a pairs table names, through the Hadoop FileSystem API with the job's
 * Hadoop configuration. A plain path or a {@code file:} URI is a file on the executor's own disk,
 * read in place by trajeval's readers (bags included). Any other scheme ({@code hdfs:},
 * {@code s3a:}, {@code abfs:}, {@code gs:}, ...) is streamed once from its file system into memory
 * ({@link InputBytes}, never copied to a local disk) and read from there with the same numbers and
 * SHA-256 as the same file on a local disk; its source in reports and messages is the URI as written.
 * Bags are refused from those schemes (their readers seek in a local file). Serializable: the
 * driver's Hadoop settings travel to the executors as text.
 */
final class PairFiles implements TrajectoryFiles, Serializable {
    private static final long serialVersionUID = 1L;
    /** A URI scheme of two letters or more (one letter is a Windows drive). */
    private static final Pattern SCHEME = Pattern.compile("^([A-Za-z][A-Za-z0-9+.-]+):");

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
     * @return the text, when it names a file
     * @throws InputException (UNREADABLE) on an empty value
     */
    static String check(String text, String column) {
        if (text == null || text.isBlank()) {
            throw new InputException(null, 0, column, InputProblem.UNREADABLE,
                    "column '" + column + "' must name a trajectory file (a path or a Hadoop URI), found none", text);
        }
        return text;
    }

    @Override
    public LoadedTrajectory read(String text, ReadOptions options) {
        var m = SCHEME.matcher(text);
        if (!m.find()) {
            return TrajectoryFiles.LOCAL.read(text, options); // a plain path
        }
        String scheme = m.group(1);
        org.apache.hadoop.fs.Path path = new org.apache.hadoop.fs.Path(text);
        if ("file".equalsIgnoreCase(scheme)) {
            return TrajectoryReader.read(localFile(text, path), options);
        }
        InputBytes bytes = InputBytes.read(text, () -> {
            FileSystem fs = fileSystem(path.toUri(), scheme);
            FileStatus status = fs.getFileStatus(path); // FileNotFoundException: "the file does not exist"
            if (status.isDirectory()) {
                throw new IOException("this is a directory, not a file");
            }
            return fs.open(path);
        }, options.maxBytes());
        return TrajectoryReader.read(bytes, options);
    }

    private FileSystem fileSystem(URI uri, String scheme) throws IOException {
        try {
            return FileSystem.get(uri, configuration());
        } catch (UnsupportedFileSystemException e) {
            throw notOnClassPath(scheme, e);
        } catch (RuntimeException e) {
            // Hadoop's configuration names the class (fs.s3a.impl) but its module is missing
            if (e.getCause() instanceof ClassNotFoundException) {
                throw notOnClassPath(scheme, e);
            }
            throw e;
        }
    }

    private static IOException notOnClassPath(String scheme, Exception e) {
        return new IOException("no Hadoop FileSystem for scheme '" + scheme + "' on the class path"
                + ("s3a".equalsIgnoreCase(scheme) ? " (s3a: add hadoop-aws and the AWS SDK bundle, see the README)"
                        : ""), e);
    }

    private Path localFile(String text, org.apache.hadoop.fs.Path path) {
        try {
            return FileSystem.getLocal(configuration()).pathToFile(path).toPath();
        } catch (IOException | IllegalArgumentException e) {
            throw new InputException(text, 0, null, InputProblem.UNREADABLE, "not a local file URI: "
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
