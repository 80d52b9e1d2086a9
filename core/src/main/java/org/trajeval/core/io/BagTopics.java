package org.trajeval.core.io;

import java.nio.file.Path;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.io.bag.BagChannel;
import org.trajeval.core.io.bag.BagContainer;
import org.trajeval.core.io.bag.BagLimits;
import org.trajeval.core.io.bag.Bags;

/** The refusal for a bag read as a trajectory file without a topic: it lists the bag's topics. */
final class BagTopics {
    private BagTopics() {
    }

    static InputException needed(Path path, String source) {
        StringBuilder topics = new StringBuilder();
        try (BagContainer bag = Bags.open(path, source, BagLimits.DEFAULT)) {
            for (BagChannel c : bag.channels()) {
                if (topics.indexOf(c.topic() + " ") < 0) {
                    topics.append(topics.length() == 0 ? "" : ", ").append(c.topic()).append(" (").append(c.type())
                            .append(')');
                }
            }
        }
        return new InputException(source, 0, null, InputProblem.UNKNOWN_TOPIC, "this is a bag: name the topic to read "
                + "(--ref-topic/--est-topic T, or FILE:TOPIC); its topics are: "
                + (topics.length() == 0 ? "(none)" : topics), null);
    }
}
