package org.trajeval.core.io;

/**
 * Layout of a planar CSV file with a header row.
 *
 * @param timeColumn header name of the timestamp column
 * @param xColumn header name of x (m)
 * @param yColumn header name of y (m)
 * @param yawColumn header name of yaw (rad)
 * @param delimiter field delimiter
 * @param timeUnit unit of the timestamp column
 */
public record CsvLayout(String timeColumn, String xColumn, String yColumn, String yawColumn, char delimiter,
        TimeUnit timeUnit) {
    /** {@code t,x,y,yaw}, comma, seconds. */
    public static final CsvLayout DEFAULT = new CsvLayout("t", "x", "y", "yaw", ',', TimeUnit.S);
}
