package org.trajeval.core.io;

import java.util.List;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;

/**
 * Where the columns t, x, y, yaw of a {@link CsvLayout} are in a header row.
 *
 * @param index field index of t, x, y, yaw in that order
 * @param names the column names t, x, y, yaw (as configured)
 * @param units their units, e.g. "(s)", "(m)", "(m)", "(rad)"
 * @param fieldCount number of fields of the header, which every row must have
 */
record CsvColumns(int[] index, String[] names, String[] units, int fieldCount) {

    /**
     * Finds the layout's columns in a header (names compared exactly, after trimming).
     *
     * @throws InputException {@link InputProblem#MISSING_COLUMN} naming the missing column and the header found
     */
    static CsvColumns locate(List<String> header, CsvLayout layout, String source, long line) {
        String[] names = {layout.timeColumn(), layout.xColumn(), layout.yColumn(), layout.yawColumn()};
        String[] units = {"(" + layout.timeUnit().id() + ")", "(m)", "(m)", "(rad)"};
        int[] index = new int[4];
        for (int k = 0; k < 4; k++) {
            index[k] = header.indexOf(names[k]);
            if (index[k] < 0) {
                String wanted = String.join(String.valueOf(layout.delimiter()), names);
                throw new InputException(source, line, names[k], InputProblem.MISSING_COLUMN,
                        "the header must name the column '" + names[k] + "' " + units[k] + " (columns " + wanted
                                + ", delimiter '" + layout.delimiter() + "'; other names with the CSV layout options)",
                        String.join(String.valueOf(layout.delimiter()), header));
            }
        }
        for (int k = 0; k < 4; k++) {
            if (header.lastIndexOf(names[k]) != index[k]) {
                throw new InputException(source, line, names[k], InputProblem.DUPLICATE_COLUMN,
                        "the header must name the column '" + names[k] + "' once, it names it in fields "
                                + (index[k] + 1) + " and " + (header.lastIndexOf(names[k]) + 1),
                        String.join(String.valueOf(layout.delimiter()), header));
            }
        }
        return new CsvColumns(index, names, units, header.size());
    }

    /** @return "t,x,y,yaw" style description of the header for messages */
    static String describe(List<String> header, char delimiter) {
        return "as the header: " + String.join(String.valueOf(delimiter), header);
    }
}
