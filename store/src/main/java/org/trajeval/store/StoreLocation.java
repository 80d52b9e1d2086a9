package org.trajeval.store;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.Map;
import java.util.Properties;
import java.util.regex.Pattern;

/**
 * Where the results store lives and how to log in, from a {@code --db} value and the environment.
 *
 * <p>A {@code --db} value is a SQLite file path ({@code trajeval.db}), a {@code jdbc:sqlite:PATH}
 * URL or a {@code jdbc:postgresql://HOST:PORT/DB[?sslmode=verify-full&sslrootcert=CA.pem]} URL.
 * Secrets never come from the command line: a URL holding {@code password=} is refused; the user
 * comes from the URL's {@code user=} or {@code TRAJEVAL_DB_USER}, the password from
 * {@code TRAJEVAL_DB_PASSWORD} or the first line of the file named by
 * {@code TRAJEVAL_DB_PASSWORD_FILE}. {@link #toString()} and {@link #display()} never show the
 * password or the URL's query.
 */
public final class StoreLocation {
    /** Environment variable holding the database user. */
    public static final String USER_ENV = "TRAJEVAL_DB_USER";
    /** Environment variable holding the database password. */
    public static final String PASSWORD_ENV = "TRAJEVAL_DB_PASSWORD";
    /** Environment variable naming a file whose first line is the database password. */
    public static final String PASSWORD_FILE_ENV = "TRAJEVAL_DB_PASSWORD_FILE";

    private static final Pattern SECRET_IN_URL = Pattern.compile("(?i)[?&;](password|sslpassword)=");

    private final String jdbcUrl;
    private final Dialect dialect;
    private final String user;
    private final String password;

    private StoreLocation(String jdbcUrl, Dialect dialect, String user, String password) {
        this.jdbcUrl = jdbcUrl;
        this.dialect = dialect;
        this.user = user;
        this.password = password;
    }

    /**
     * @param db the {@code --db} value
     * @param env the environment (System.getenv() in the launchers)
     * @throws StoreException BAD_LOCATION on an unknown URL scheme, a password in the URL or an
     *     unreadable password file
     */
    public static StoreLocation parse(String db, Map<String, String> env) {
        if (db == null || db.isBlank()) {
            throw new StoreException(StoreException.Problem.BAD_LOCATION,
                    "--db: expected a SQLite file or a jdbc:sqlite: / jdbc:postgresql: URL, found nothing", null);
        }
        if (SECRET_IN_URL.matcher(db).find()) {
            throw new StoreException(StoreException.Problem.BAD_LOCATION, "--db: the URL holds a password; "
                    + "command lines and URLs end up in shell histories, process lists and logs. Put it in "
                    + PASSWORD_ENV + " or in a file named by " + PASSWORD_FILE_ENV, null);
        }
        String lower = db.toLowerCase(Locale.ROOT);
        if (lower.startsWith("jdbc:postgresql:")) {
            return new StoreLocation(db, Dialect.POSTGRESQL, env.get(USER_ENV), password(env));
        }
        if (lower.startsWith("jdbc:sqlite:")) {
            return new StoreLocation(db, Dialect.SQLITE, null, null);
        }
        if (lower.startsWith("jdbc:")) {
            throw new StoreException(StoreException.Problem.BAD_LOCATION, "--db: expected a SQLite file or a "
                    + "jdbc:sqlite: / jdbc:postgresql: URL, found \"" + display(db) + "\"", null);
        }
        return new StoreLocation("jdbc:sqlite:" + Path.of(db).toAbsolutePath(), Dialect.SQLITE, null, null);
    }

    /** @return a SQLite store in this file */
    public static StoreLocation sqlite(Path file) {
        return new StoreLocation("jdbc:sqlite:" + file.toAbsolutePath(), Dialect.SQLITE, null, null);
    }

    private static String password(Map<String, String> env) {
        String direct = env.get(PASSWORD_ENV);
        String file = env.get(PASSWORD_FILE_ENV);
        if (direct != null && file != null) {
            throw new StoreException(StoreException.Problem.BAD_LOCATION,
                    "set either " + PASSWORD_ENV + " or " + PASSWORD_FILE_ENV + ", not both", null);
        }
        if (file == null) {
            return direct;
        }
        try {
            String text = Files.readString(Path.of(file), StandardCharsets.UTF_8);
            int nl = text.indexOf('\n');
            return (nl < 0 ? text : text.substring(0, nl)).strip();
        } catch (IOException | RuntimeException e) {
            throw new StoreException(StoreException.Problem.BAD_LOCATION,
                    PASSWORD_FILE_ENV + ": cannot read the password file " + file + " (" + e.getClass().getSimpleName()
                            + ")", e);
        }
    }

    /** @return the JDBC URL (no secret: a URL with a password is refused) */
    public String jdbcUrl() {
        return jdbcUrl;
    }

    /** @return the database kind */
    public Dialect dialect() {
        return dialect;
    }

    /** @return the connection properties: user and password when set */
    Properties connectionProperties() {
        Properties p = new Properties();
        if (user != null) {
            p.setProperty("user", user);
        }
        if (password != null) {
            p.setProperty("password", password);
        }
        return p;
    }

    /** @return the URL without its query (which may name users and files), for messages and logs */
    public String display() {
        return display(jdbcUrl);
    }

    private static String display(String url) {
        int q = url.indexOf('?');
        return q < 0 ? url : url.substring(0, q) + "?...";
    }

    @Override
    public String toString() {
        return display();
    }
}
