package org.trajeval.core.options;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;

/**
 * Settings written as a tree (a YAML or JSON mapping) as a flat list. A nested mapping is a
 * shorthand for keys joined by '_': {@code rpe: {delta: 1, unit: s}} is {@code rpe_delta: 1,
 * rpe_unit: s}; a list of scalars is its items joined by commas; a null value is no setting.
 */
public final class SettingsTree {
    private SettingsTree() {
    }

    /**
     * @param tree the mapping (values: String, Number, Boolean, List, Map or null)
     * @param path key path of the mapping in its file ({@code metrics}), for refusals; "" at the top
     * @param source the file or event, for refusals
     * @return the settings in the mapping's order
     * @throws InputException on a list holding anything but scalars
     */
    public static List<SettingText> flatten(Map<String, ?> tree, String path, String source) {
        List<SettingText> out = new ArrayList<>();
        flatten(tree, "", path, source, out);
        return out;
    }

    private static void flatten(Map<String, ?> tree, String keyPrefix, String path, String source,
            List<SettingText> out) {
        for (Map.Entry<String, ?> e : tree.entrySet()) {
            String where = path.isEmpty() ? e.getKey() : path + "." + e.getKey();
            String key = keyPrefix + e.getKey();
            Object v = e.getValue();
            if (v == null) {
                continue;
            }
            if (v instanceof Map<?, ?> m) {
                @SuppressWarnings("unchecked")
                Map<String, ?> sub = (Map<String, ?>) m;
                flatten(sub, key + "_", where, source, out);
            } else if (v instanceof List<?> l) {
                List<String> items = new ArrayList<>();
                for (Object item : l) {
                    if (item == null || item instanceof Map || item instanceof List) {
                        throw new InputException(source, 0, where, InputProblem.INVALID_CONFIGURATION,
                                "'" + where + "': expected a list of plain values", String.valueOf(item));
                    }
                    items.add(String.valueOf(item));
                }
                out.add(new SettingText(key, String.join(",", items), where));
            } else {
                out.add(new SettingText(key, String.valueOf(v), where));
            }
        }
    }
}
