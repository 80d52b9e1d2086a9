/**
 * The SQLite JDBC driver's native library, loaded from one fixed file by every SQLite user (the
 * results store, the rosbag2 sqlite3 reader). Internal: may change in any release; the public API is
 * {@link org.trajeval.api}.
 */
package org.trajeval.core.io.sqlite;
