package org.trajeval.core.io.sqlite;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.JarURLConnection;
import java.net.URL;
import java.net.URLConnection;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.jar.JarEntry;
import java.util.zip.CRC32;

/**
 * Where the SQLite JDBC driver loads its native library from: one fixed file instead of a fresh
 * copy in the temp folder at every start.
 *
 * <p>Left alone, the driver (sqlite-jdbc 3.54, {@code SQLiteJDBCLoader}) copies the 1.1 MB
 * library for the platform out of its jar into {@code java.io.tmpdir} under a new random name at
 * every JVM start, compares the copy with the jar byte by byte, and deletes it on a normal exit
 * only: a killed process leaves the copy and its {@code .lck} behind, and the driver's clean-up at
 * the next start spares every copy that has a {@code .lck}. To name the platform it runs
 * {@code uname -o} in a child process and resolves every entry of {@code /proc/self/map_files}. It
 * skips all of that when the system property {@code org.sqlite.lib.path} names a folder holding
 * the library, which this class sets before the first SQLite connection of the results store and
 * of the rosbag2 sqlite3 reader, unless the user set it (or {@code org.sqlite.lib.name}):
 * <ol>
 *   <li>the distribution's copy: {@value #DIST_PROPERTY}{@code =DIR} (the launchers pass
 *       {@code APP_HOME/lib/sqlite-native}) holding {@code DIR/OS/ARCH/LIB} with the jar entry's
 *       size, used in place (read-only installs and a missing {@code /tmp} included);</li>
 *   <li>else a per-version copy in the user's cache,
 *       {@code $XDG_CACHE_HOME/trajeval/sqlite-jdbc-VERSION-CRC/OS/ARCH/LIB} (default
 *       {@code ~/.cache}), checked against the jar entry's size and CRC-32 at every start and, when
 *       missing or different (half written, damaged), written again: to a temporary file in the same
 *       folder, checked, then renamed over it atomically (a concurrent start sees the old file or
 *       the new one, never part of one).</li>
 * </ol>
 * Anything else (a platform not named without a child process: 32-bit ARM, Android; no library
 * in the jar; an unwritable cache) keeps the driver's own behaviour; when that cannot work either
 * (its temp folder missing or read-only, no library on {@code java.library.path}), {@link #configure}
 * fails with one line saying so (the store's UNAVAILABLE, the bag reader's refusal) instead of the
 * driver's logged stack traces. When {@code java.io.tmpdir} is not a writable folder,
 * {@code org.sqlite.tmpdir} is pointed at the library's folder too, unless set: the driver's
 * clean-up lists that folder at every start (deleting its old copies) and would log a failure
 * otherwise.
 */
public final class SqliteNativeLibrary {
    /** System property naming the distribution's folder of native libraries, laid out as OS/ARCH/LIB. */
    static final String DIST_PROPERTY = "trajeval.sqlite.native";
    /** The driver's system property naming the folder it loads its library from (set by {@link #configure}). */
    public static final String LIB_PATH = "org.sqlite.lib.path";
    static final String LIB_NAME = "org.sqlite.lib.name";
    static final String DRIVER_TMPDIR = "org.sqlite.tmpdir";
    private static final String JAR_FOLDER = "org/sqlite/native/";
    private static final String VERSION_RESOURCE = "META-INF/maven/org.xerial/sqlite-jdbc/VERSION";

    /** Age after which a temporary copy in the cache is a dead start's leftover. */
    static final java.time.Duration STALE_TEMPORARY = java.time.Duration.ofMinutes(10);

    private static boolean configured;

    private SqliteNativeLibrary() {
    }

    /** The jar's copy of the library: its size (bytes) and CRC-32, as its zip entry records them. */
    record Entry(long size, long crc) {
    }

    /**
     * Points the driver at a fixed copy of its library, once per JVM (see the class comment).
     *
     * @param env the environment (XDG_CACHE_HOME)
     * @throws IllegalStateException when neither a fixed copy nor the driver's own way can work: its
     *     message is one line naming the fix (tried again at the next call)
     */
    public static synchronized void configure(Map<String, String> env) {
        if (configured) {
            return;
        }
        if (System.getProperty(LIB_PATH) != null || System.getProperty(LIB_NAME) != null) {
            configured = true;
            return;
        }
        Optional<String> platform;
        try {
            platform = platform(System.getProperty("os.name", ""), System.getProperty("os.arch", ""),
                    SqliteNativeLibrary::linuxIsMusl, isAndroid());
        } catch (IllegalStateException e) {
            platform = Optional.empty(); // /proc/self/exe unreadable: musl or not is the driver's to find out
        }
        String lib = System.mapLibraryName("sqlitejdbc");
        ClassLoader loader = SqliteNativeLibrary.class.getClassLoader();
        URL resource = platform.isEmpty() ? null : loader.getResource(JAR_FOLDER + platform.get() + "/" + lib);
        if (resource == null) {
            configured = true;
            return; // the driver's own way
        }
        Path folder;
        try {
            folder = locate(resource, platform.get(), lib, env, loader);
        } catch (IOException | RuntimeException e) {
            if (!driverCanLoad(lib)) {
                // the driver would fail too, logging stack traces: one line instead (tried again at the next open)
                throw new IllegalStateException("cannot load SQLite's native library: "
                        + "no copy in the cache (" + e.getClass().getSimpleName() + ": " + e.getMessage()
                        + ") and the temp folder " + driverTmpdir() + " is missing or read-only. Set XDG_CACHE_HOME "
                        + "or -Djava.io.tmpdir to a writable folder, or -D" + LIB_PATH + " to a folder holding "
                        + lib, e);
            }
            configured = true;
            return; // the driver's own extraction into the temp folder
        }
        configured = true;
        System.setProperty(LIB_PATH, folder.toString());
        if (System.getProperty(DRIVER_TMPDIR) == null && !writableFolder(Path.of(driverTmpdir()))) {
            System.setProperty(DRIVER_TMPDIR, folder.toString());
        }
    }

    /**
     * @return the folder holding a good copy of the library: the distribution's, else the cache's
     * @throws IOException when the cache has no good copy and none can be written there
     */
    private static Path locate(URL resource, String platform, String lib, Map<String, String> env,
            ClassLoader loader) throws IOException {
        Entry expected = entry(resource);
        String dist = System.getProperty(DIST_PROPERTY);
        if (dist != null) {
            Path folder = Path.of(dist, platform).toAbsolutePath();
            Path file = folder.resolve(lib);
            if (Files.isRegularFile(file) && Files.size(file) == expected.size()) {
                return folder;
            }
        }
        Path cache = cacheRoot(env, System.getProperty("user.home"))
                .orElseThrow(() -> new IOException("no home folder and no XDG_CACHE_HOME"));
        // the version file says 3.54.1 for 3.54.1.0: the CRC keeps two builds of one version apart
        Path folder = cache.resolve("sqlite-jdbc-" + version(loader) + "-" + String.format("%08x", expected.crc()))
                .resolve(platform);
        return ensureCopy(resource, expected, folder.resolve(lib)).getParent();
    }

    private static String driverTmpdir() {
        return System.getProperty(DRIVER_TMPDIR, System.getProperty("java.io.tmpdir", ""));
    }

    private static boolean writableFolder(Path p) {
        return Files.isDirectory(p) && Files.isWritable(p);
    }

    /** @return whether the driver's own ways may work: extraction into its temp folder, or java.library.path */
    private static boolean driverCanLoad(String lib) {
        if (writableFolder(Path.of(driverTmpdir()))) {
            return true;
        }
        for (String dir : System.getProperty("java.library.path", "").split(java.io.File.pathSeparator)) {
            if (!dir.isEmpty() && Files.isRegularFile(Path.of(dir, lib))) {
                return true;
            }
        }
        return false;
    }

    /**
     * The driver's folder for a platform ({@code org/sqlite/native/FOLDER}), for the platforms it
     * names from system properties alone.
     *
     * @param musl asked on Linux only: whether this JVM runs on musl libc (Alpine)
     * @return e.g. {@code Linux/x86_64}; empty where the driver needs a child process ({@code uname})
     *     or Android's checks, or ships nothing
     */
    static Optional<String> platform(String osName, String osArch, java.util.function.BooleanSupplier musl,
            boolean android) {
        String arch = switch (osArch.toLowerCase(Locale.ROOT)) {
            case "amd64", "x86_64", "x86-64" -> "x86_64";
            case "aarch64", "arm64" -> "aarch64";
            default -> null; // 32-bit ARM: the driver asks uname -m and readelf; others: rare, its own way
        };
        if (arch == null || android) {
            return Optional.empty();
        }
        if (osName.contains("Windows")) {
            return Optional.of("Windows/" + arch);
        }
        if (osName.contains("Mac") || osName.contains("Darwin")) {
            return Optional.of("Mac/" + arch);
        }
        if (osName.contains("Linux")) {
            return Optional.of((musl.getAsBoolean() ? "Linux-Musl/" : "Linux/") + arch);
        }
        return Optional.empty();
    }

    /**
     * Whether this JVM runs on musl libc (Alpine): the dynamic loader its executable names (ELF
     * {@code PT_INTERP}, in the first page: {@code /lib/ld-musl-x86_64.so.1} against glibc's
     * {@code /lib64/ld-linux-x86-64.so.2}). The driver resolves every entry of
     * {@code /proc/self/map_files} for the same answer (a JVM maps the C library its executable's
     * loader loads).
     */
    private static boolean linuxIsMusl() {
        byte[] head = new byte[4096];
        int n;
        try (InputStream in = Files.newInputStream(Path.of("/proc/self/exe"))) {
            n = in.readNBytes(head, 0, head.length);
        } catch (IOException | RuntimeException e) {
            throw new IllegalStateException("cannot read /proc/self/exe", e);
        }
        return new String(head, 0, n, StandardCharsets.ISO_8859_1).contains("ld-musl-");
    }

    /** The driver's tests for Android, without its {@code uname -o} (Termux runs on Android, whose files it checks). */
    private static boolean isAndroid() {
        return System.getProperty("java.runtime.name", "").toLowerCase(Locale.ROOT).contains("android")
                || Files.exists(Path.of("/system/lib/libGLESv1_CM.so"))
                || Files.exists(Path.of("/system/lib64/libGLESv1_CM.so"));
    }

    /** @return the jar entry's size and CRC-32 (from the jar's directory, nothing inflated), else the bytes' */
    static Entry entry(URL resource) throws IOException {
        URLConnection c = resource.openConnection();
        if (c instanceof JarURLConnection jar) {
            JarEntry e = jar.getJarEntry();
            if (e.getSize() >= 0 && e.getCrc() >= 0) {
                return new Entry(e.getSize(), e.getCrc());
            }
        }
        try (InputStream in = resource.openStream()) {
            return copy(in, OutputStream.nullOutputStream());
        }
    }

    /**
     * @return {@code $XDG_CACHE_HOME/trajeval} when absolute, else {@code HOME/.cache/trajeval};
     *     empty without a home
     */
    static Optional<Path> cacheRoot(Map<String, String> env, String userHome) {
        String xdg = env.get("XDG_CACHE_HOME");
        if (xdg != null && !xdg.isEmpty() && Path.of(xdg).isAbsolute()) {
            return Optional.of(Path.of(xdg, "trajeval"));
        }
        if (userHome == null || userHome.isEmpty() || "?".equals(userHome)) {
            return Optional.empty();
        }
        return Optional.of(Path.of(userHome, ".cache", "trajeval"));
    }

    private static String version(ClassLoader loader) throws IOException {
        URL v = loader.getResource(VERSION_RESOURCE);
        if (v == null) {
            return "unknown";
        }
        java.util.Properties p = new java.util.Properties();
        try (InputStream in = v.openStream()) {
            p.load(in);
        }
        return p.getProperty("version", "unknown").trim().replaceAll("[^0-9.]", "");
    }

    /**
     * Makes {@code target} a copy of the resource: kept when its size and CRC-32 match, else
     * written to a temporary file beside it, checked, and renamed over it.
     *
     * @return target
     * @throws IOException when the folder cannot be written (or the copy comes out different)
     */
    static Path ensureCopy(URL resource, Entry expected, Path target) throws IOException {
        if (Files.isRegularFile(target) && Files.size(target) == expected.size()) {
            try (InputStream in = Files.newInputStream(target)) {
                if (copy(in, OutputStream.nullOutputStream()).equals(expected)) {
                    return target;
                }
            }
        }
        Path folder = Files.createDirectories(target.getParent());
        deleteStaleTemporaries(folder, "." + target.getFileName());
        Path tmp = Files.createTempFile(folder, "." + target.getFileName(), ".tmp");
        try {
            Entry written;
            try (InputStream in = resource.openStream(); OutputStream out = Files.newOutputStream(tmp)) {
                written = copy(in, out);
            }
            if (!written.equals(expected) || Files.size(tmp) != expected.size()) {
                throw new IOException("the copy of " + resource + " differs from the jar's entry");
            }
            Files.move(tmp, target, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
            return target;
        } finally {
            Files.deleteIfExists(tmp);
        }
    }

    /**
     * Deletes temporary copies older than {@link #STALE_TEMPORARY}: left by a start killed while
     * writing (a concurrent writer's is younger).
     */
    private static void deleteStaleTemporaries(Path folder, String prefix) throws IOException {
        long before = System.currentTimeMillis() - STALE_TEMPORARY.toMillis();
        try (java.nio.file.DirectoryStream<Path> s = Files.newDirectoryStream(folder, prefix + "*.tmp")) {
            for (Path p : s) {
                try {
                    if (Files.getLastModifiedTime(p).toMillis() < before) {
                        Files.deleteIfExists(p);
                    }
                } catch (IOException e) {
                    // another start deleted it, or it cannot be: the copy is written beside it anyway
                }
            }
        }
    }

    /** Copies a stream, counting its bytes and their CRC-32. */
    private static Entry copy(InputStream in, OutputStream out) throws IOException {
        CRC32 crc = new CRC32();
        byte[] buffer = new byte[64 * 1024];
        long size = 0;
        for (int n; (n = in.read(buffer)) > 0;) {
            crc.update(buffer, 0, n);
            out.write(buffer, 0, n);
            size += n;
        }
        return new Entry(size, crc.getValue());
    }
}
