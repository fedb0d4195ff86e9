package sitcov.engine;

import java.util.AbstractList;
import java.util.List;
import java.util.RandomAccess;

/**
 * A read-only view of a list its owner keeps changing, made once and handed out many times a tick.
 * The JDK's unmodifiable view would do, but a checkpoint cannot see which list it views; this one
 * it copies with the list.
 */
public final class ReadOnlyView<T> extends AbstractList<T> implements RandomAccess {
    private List<T> viewed;

    public ReadOnlyView(List<T> viewed) {
        this.viewed = viewed;
    }

    @Override
    public T get(int index) {
        return viewed.get(index);
    }

    @Override
    public int size() {
        return viewed.size();
    }
}
