package sitcov.seam;

import java.util.AbstractList;
import java.util.List;
import java.util.RandomAccess;

/**
 * A read-only view of a list a distortion keeps refilling, made once: the JDK's unmodifiable view
 * would do, but a checkpoint cannot see which list it views, and this one it copies with the list.
 */
final class ReadOnly<T> extends AbstractList<T> implements RandomAccess {
    private List<T> viewed;

    ReadOnly(List<T> viewed) {
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
