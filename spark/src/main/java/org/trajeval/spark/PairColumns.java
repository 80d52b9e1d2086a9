package org.trajeval.spark;

import java.io.Serializable;
import java.util.ArrayList;
import java.util.List;
import org.apache.spark.sql.Row;
import org.apache.spark.sql.types.DataTypes;
import org.apache.spark.sql.types.StructField;
import org.apache.spark.sql.types.StructType;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.options.Setting;
import org.trajeval.core.options.SettingText;

/**
 * The roles of a pairs table's columns: {@value #REF} and {@value #EST} (strings: paths or
 * Hadoop URIs), per-row settings (a column named as a setting's key in the one options model:
 * {@code format}, {@code convention}, {@code alignment}, {@code rpe_delta}, ...; a null cell means
 * the job's value), and everything else, passed through. Checked once on the driver.
 */
final class PairColumns implements Serializable {
    private static final long serialVersionUID = 1L;

    /** Column of the reference trajectory. */
    static final String REF = "ref";
    /** Column of the estimate. */
    static final String EST = "est";

    private final int ref;
    private final int est;
    private final int[] settingIndex;
    private final String[] settingKey;

    private PairColumns(int ref, int est, int[] settingIndex, String[] settingKey) {
        this.ref = ref;
        this.est = est;
        this.settingIndex = settingIndex;
        this.settingKey = settingKey;
    }

    /**
     * @param schema the pairs table's schema
     * @param source how to name the table in refusals
     * @throws InputException (MISSING_COLUMN) without string columns ref and est; (DUPLICATE_COLUMN) when
     *     a column has the name of a result column
     */
    static PairColumns of(StructType schema, String source) {
        List<String> names = List.of(schema.fieldNames());
        for (String need : List.of(REF, EST)) {
            int i = names.indexOf(need);
            if (i < 0) {
                throw new InputException(source, 0, need, InputProblem.MISSING_COLUMN, "the pairs table needs "
                        + "string columns 'ref' (reference) and 'est' (estimate); its columns are " + names, null);
            }
            if (schema.fields()[i].dataType() != DataTypes.StringType) {
                throw new InputException(source, 0, need, InputProblem.INVALID_OPTION, "column '" + need
                        + "' must hold strings (paths or URIs)", schema.fields()[i].dataType().simpleString());
            }
        }
        for (StructField f : ResultSchema.RESULT.fields()) {
            if (names.contains(f.name())) {
                throw new InputException(source, 0, f.name(), InputProblem.DUPLICATE_COLUMN, "column '" + f.name()
                        + "' is a result column of trajeval-spark; rename it in the pairs table", f.name());
            }
        }
        List<Integer> idx = new ArrayList<>();
        List<String> keys = new ArrayList<>();
        for (int i = 0; i < names.size(); i++) {
            if (Setting.fromKey(names.get(i)) != null) {
                idx.add(i);
                keys.add(names.get(i));
            }
        }
        return new PairColumns(names.indexOf(REF), names.indexOf(EST), idx.stream().mapToInt(Integer::intValue)
                .toArray(), keys.toArray(String[]::new));
    }

    /** @return the row's reference path as written */
    String ref(Row row) {
        return row.isNullAt(ref) ? null : row.getString(ref);
    }

    /** @return the row's estimate path as written */
    String est(Row row) {
        return row.isNullAt(est) ? null : row.getString(est);
    }

    /** @return the row's own settings (non-null cells of settings columns), as text named by their column */
    List<SettingText> settings(Row row) {
        List<SettingText> out = new ArrayList<>();
        for (int k = 0; k < settingIndex.length; k++) {
            if (!row.isNullAt(settingIndex[k])) {
                String text = String.valueOf(row.get(settingIndex[k]));
                if (!text.isEmpty()) {
                    out.add(new SettingText(settingKey[k], text, "column " + settingKey[k]));
                }
            }
        }
        return out;
    }
}
