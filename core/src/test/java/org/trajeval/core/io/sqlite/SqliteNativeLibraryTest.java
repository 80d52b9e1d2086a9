package org.trajeval.core.io.sqlite;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.trajeval.core.io.sqlite.NativeLibraryChild.files;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The SQLite driver's native library comes from one fixed, checked file: opening a SQLite file
 * after {@link SqliteNativeLibrary#configure} (in child JVMs, as users run trajeval) leaves nothing
 * in the temp folder, even when killed, and a damaged copy is replaced.
 */
class SqliteNativeLibraryTest {
    private static final String LIB = System.mapLibraryName("sqlitejdbc");

    @TempDir
    Path dir;

    record Run(int code, List<String> out, String err) {
    }

    /** Starts {@link SqliteStart} with this temp folder and cache, waits for it to end. */
    private Run start(Path tmp, Path cache, String... jvmOptions) throws Exception {
        Process p = child(tmp, cache, false, jvmOptions);
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "the child JVM ended");
        return new Run(p.exitValue(), lines(p.getInputStream()), new String(p.getErrorStream().readAllBytes(),
                StandardCharsets.UTF_8));
    }

    private Process child(Path tmp, Path cache, boolean wait, String... jvmOptions) throws IOException {
        String db = dir.resolve("test.db").toString();
        return NativeLibraryChild.start(tmp, cache, List.of(jvmOptions), SqliteStart.class,
                wait ? List.of(db, "wait") : List.of(db));
    }

    private static List<String> lines(InputStream in) throws IOException {
        return new String(in.readAllBytes(), StandardCharsets.UTF_8).lines().toList();
    }


    private static byte[] jarCopy(String platform) throws IOException {
        try (InputStream in = SqliteNativeLibraryTest.class.getClassLoader()
                .getResourceAsStream("org/sqlite/native/" + platform + "/" + LIB)) {
            return in.readAllBytes();
        }
    }

    /** The driver's own answer for this JVM (it runs uname -o; fine in a test). */
    private static String driversPlatform() throws Exception {
        return (String) Class.forName("org.sqlite.util.OSInfo").getMethod("getNativeLibFolderPathForCurrentOS")
                .invoke(null);
    }

    @Test
    void anOpenAndAKilledConnectionLeaveNothingInTheTempFolder() throws Exception {
        Path tmp = Files.createDirectories(dir.resolve("tmp"));
        Process p = child(tmp, dir.resolve("cache"), true);
        try {
            BufferedReader out = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8));
            String libPath = out.readLine();
            assertEquals("open", out.readLine(), "the file opened (library folder " + libPath + ")");
            assertEquals(List.of(), files(tmp), "nothing in the temp folder while the connection is open");
        } finally {
            p.destroyForcibly(); // SIGKILL: no shutdown hook, no deleteOnExit
            assertTrue(p.waitFor(60, TimeUnit.SECONDS));
        }
        assertEquals(List.of(), files(tmp), "nothing in the temp folder after a kill");
    }

    @Test
    void fiveStartsShareOneCopyInTheCacheAndWriteNothingElse() throws Exception {
        Path tmp = Files.createDirectories(dir.resolve("tmp"));
        Path cache = dir.resolve("cache");
        for (int i = 0; i < 5; i++) {
            Run r = start(tmp, cache);
            assertEquals(0, r.code(), r.err());
            assertEquals("", r.err());
            assertTrue(r.out().get(0).startsWith(cache.toString()), r.out().get(0));
        }
        assertEquals(List.of(), files(tmp));
        List<Path> copies = files(cache);
        assertEquals(1, copies.size(), copies.toString());
        assertTrue(copies.get(0).endsWith(Path.of(driversPlatform(), LIB)), copies.toString());
        assertArrayEquals(jarCopy(driversPlatform()), Files.readAllBytes(copies.get(0)));
    }

    @Test
    void aHalfWrittenOrDamagedCopyInTheCacheIsReplacedAndADeadStartsTemporaryDeleted() throws Exception {
        Path tmp = Files.createDirectories(dir.resolve("tmp"));
        Path cache = dir.resolve("cache");
        assertEquals(0, start(tmp, cache).code());
        Path copy = files(cache).get(0);
        byte[] good = jarCopy(driversPlatform());

        Files.write(copy, java.util.Arrays.copyOf(good, good.length / 2)); // a start killed while writing
        Run r = start(tmp, cache);
        assertEquals(0, r.code(), r.err());
        assertArrayEquals(good, Files.readAllBytes(copy));

        // a start killed while writing its temporary copy, long ago, and one writing now
        Path dead = Files.write(copy.resolveSibling("." + LIB + "123.tmp"), new byte[1000]);
        Files.setLastModifiedTime(dead, java.nio.file.attribute.FileTime.fromMillis(System.currentTimeMillis()
                - SqliteNativeLibrary.STALE_TEMPORARY.toMillis() - 60_000));
        Path live = Files.write(copy.resolveSibling("." + LIB + "456.tmp"), new byte[1000]);
        byte[] damaged = good.clone();
        damaged[good.length / 3] ^= 0x55; // same size, one byte different
        Files.write(copy, damaged);
        r = start(tmp, cache);
        assertEquals(0, r.code(), r.err());
        assertArrayEquals(good, Files.readAllBytes(copy));
        assertEquals(java.util.Set.of(copy, live), java.util.Set.copyOf(files(cache)),
                "the dead start's temporary copy deleted, the live one's kept, none of its own left");
    }

    @Test
    void theDistributionsCopyIsUsedInPlace() throws Exception {
        Path dist = dir.resolve("install/lib/sqlite-native");
        Path folder = Files.createDirectories(dist.resolve(driversPlatform()));
        Files.write(folder.resolve(LIB), jarCopy(driversPlatform()));
        Path cache = dir.resolve("cache");
        Path tmp = Files.createDirectories(dir.resolve("tmp"));
        Run r = start(tmp, cache, "-D" + SqliteNativeLibrary.DIST_PROPERTY + "=" + dist);
        assertEquals(0, r.code(), r.err());
        assertEquals(folder.toString(), r.out().get(0));
        assertFalse(Files.exists(cache), "no copy in the cache");
        assertEquals(List.of(), files(tmp));
    }

    @Test
    void aFolderTheUserNamedIsLeftToTheDriver() throws Exception {
        Path own = Files.createDirectories(dir.resolve("own"));
        Files.write(own.resolve(LIB), jarCopy(driversPlatform()));
        Path cache = dir.resolve("cache");
        Run r = start(Files.createDirectories(dir.resolve("tmp")), cache, "-Dorg.sqlite.lib.path=" + own);
        assertEquals(0, r.code(), r.err());
        assertEquals(own.toString(), r.out().get(0));
        assertFalse(Files.exists(cache), "no copy in the cache");
    }

    @Test
    void aMissingTempFolderDoesNotStopTheConnection() throws Exception {
        Run r = start(dir.resolve("no/such/tmp"), dir.resolve("cache"));
        assertEquals(0, r.code(), r.err());
        assertEquals("", r.err(), "nothing logged by the driver");
        assertEquals("open", r.out().get(1));
    }

    @Test
    void withoutACacheAndATempFolderConfigureFailsWithOneLine() throws Exception {
        // /proc cannot hold a new folder, even for root
        Run r = start(dir.resolve("no/such/tmp"), Path.of("/proc/trajeval-no-cache"));
        assertEquals(3, r.code(), r.err());
        assertEquals(1, r.err().strip().lines().count(), r.err());
        assertTrue(r.err().startsWith("cannot load SQLite's native library") && r.err().contains("java.io.tmpdir"),
                r.err());
    }

    @Test
    void anUnwritableCacheFallsBackToTheDriversOwnCopy() throws Exception {
        Run r = start(Files.createDirectories(dir.resolve("tmp")), Path.of("/proc/trajeval-no-cache"));
        assertEquals(0, r.code(), r.err());
        assertEquals("-", r.out().get(0), "the driver's own way");
    }

    @Test
    void thePlatformIsTheDriversOwnForThisJvm() throws Exception {
        String drivers = driversPlatform();
        Optional<String> mine = SqliteNativeLibrary.platform(System.getProperty("os.name"),
                System.getProperty("os.arch"), () -> drivers.startsWith("Linux-Musl"), false);
        assertEquals(Optional.of(drivers), mine);
    }

    @Test
    void platformsAreNamedWithoutAChildProcessOrLeftToTheDriver() {
        java.util.function.BooleanSupplier glibc = () -> false;
        java.util.function.BooleanSupplier never = () -> {
            throw new AssertionError("musl asked off Linux");
        };
        assertEquals(Optional.of("Linux/x86_64"), SqliteNativeLibrary.platform("Linux", "amd64", glibc, false));
        assertEquals(Optional.of("Linux/aarch64"), SqliteNativeLibrary.platform("Linux", "aarch64", glibc, false));
        assertEquals(Optional.of("Linux-Musl/x86_64"), SqliteNativeLibrary.platform("Linux", "amd64", () -> true,
                false));
        assertEquals(Optional.of("Mac/aarch64"), SqliteNativeLibrary.platform("Mac OS X", "aarch64", never, false));
        assertEquals(Optional.of("Windows/x86_64"), SqliteNativeLibrary.platform("Windows 11", "amd64", never, false));
        // the driver asks uname -m and readelf on 32-bit ARM, uname -o for Termux: its own way
        assertEquals(Optional.empty(), SqliteNativeLibrary.platform("Linux", "arm", never, false));
        assertEquals(Optional.empty(), SqliteNativeLibrary.platform("Linux", "aarch64", never, true));
        assertEquals(Optional.empty(), SqliteNativeLibrary.platform("SunOS", "amd64", never, false));
    }

    @Test
    void theCacheIsXdgCacheHomeElseTheHomesDotCache() {
        assertEquals(Optional.of(Path.of("/c/trajeval")), SqliteNativeLibrary.cacheRoot(Map.of("XDG_CACHE_HOME",
                "/c"), "/home/u"));
        assertEquals(Optional.of(Path.of("/home/u/.cache/trajeval")), SqliteNativeLibrary.cacheRoot(
                Map.of("XDG_CACHE_HOME", "relative"), "/home/u"));
        assertEquals(Optional.empty(), SqliteNativeLibrary.cacheRoot(Map.of(), "?"));
    }
}
