package sitcov.engine;

import java.lang.reflect.Array;
import java.lang.reflect.Field;
import java.lang.reflect.Modifier;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collection;
import java.util.EnumMap;
import java.util.EnumSet;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.PriorityQueue;
import java.util.Set;

/**
 * A deep copy of a model's object graph, the way MASON checkpoints a model, but in memory and
 * without serialization: each of the model's own objects is copied field by field (no constructor
 * runs), arrays element by element, the JDK's mutable collections rebuilt around copied elements,
 * and values that never change (enums, strings, boxed numbers, records of values, and the types the
 * caller names as immutable, such as the map) shared. Objects reached twice are copied once, so the
 * copy has the original's shape, and nothing of the copy is shared with the original that either
 * could change. What it cannot copy faithfully (a lambda that captured state, a JDK object it does
 * not know, a read-only view of a collection, a final field, which the JDK may refuse to let
 * reflection write) it refuses, naming it, rather than copy it wrongly.
 */
public final class ModelCopy {
    private static final ClassValue<Plan> PLANS = new ClassValue<>() {
        @Override
        protected Plan computeValue(Class<?> type) {
            return Plan.of(type);
        }
    };

    private final Sharing sharing;
    // a run's graph holds some hundreds of objects: room for them from the start
    private final IdentityHashMap<Object, Object> copies = new IdentityHashMap<>(1024);

    private ModelCopy(Sharing sharing) {
        this.sharing = sharing;
    }

    /**
     * Which classes copies share rather than copy: values (enums, strings, boxed numbers, records of
     * values) and exactly the classes named {@code immutable}, not their subclasses nor their
     * neighbours in a package. Make one and keep it: it remembers each class's answer.
     */
    public static final class Sharing {
        private final Set<Class<?>> immutable;
        private final ClassValue<Kind> kinds = new ClassValue<>() {
            @Override
            protected Kind computeValue(Class<?> type) {
                return Kind.of(type, immutable);
            }
        };

        public Sharing(Set<Class<?>> immutable) {
            this.immutable = Set.copyOf(immutable);
        }
    }

    /** What a copy does with an instance of a class. */
    private enum Kind {
        SHARED, ARRAY, JDK, MODEL;

        static Kind of(Class<?> type, Set<Class<?>> immutable) {
            if (isValue(type) || immutable.contains(type)) {
                return SHARED;
            }
            if (type.isRecord()) {
                // a record's fields cannot be set, so it can only be shared: it must hold nothing that changes
                for (java.lang.reflect.RecordComponent c : type.getRecordComponents()) {
                    if (of(c.getType(), immutable) != SHARED) {
                        throw new IllegalStateException("cannot checkpoint record " + type.getName() + ": its "
                                + c.getName() + " (" + c.getType().getSimpleName() + ") may change; give it"
                                + " components that are values, or make it a class");
                    }
                }
                return SHARED;
            }
            if (type.isArray()) {
                return ARRAY;
            }
            if (type.getName().startsWith("java.")) {
                return JDK;
            }
            if (type.isHidden() || type.isSynthetic()) {
                if (Plan.instanceFields(type).isEmpty()) {
                    return SHARED; // a lambda that captured nothing is a pure function
                }
                throw new IllegalStateException("cannot checkpoint " + type.getName()
                        + ": a lambda that captured state; keep that state in a named class instead");
            }
            return MODEL;
        }
    }

    /**
     * A copy of everything reachable from {@code root}, sharing only what {@code sharing} shares.
     *
     * @throws IllegalStateException naming the object on the path that cannot be copied
     */
    @SuppressWarnings("unchecked")
    public static <T> T of(T root, Sharing sharing) {
        return (T) new ModelCopy(sharing).copy(root);
    }

    private Object copy(Object original) {
        if (original == null) {
            return null;
        }
        Class<?> type = original.getClass();
        Kind kind = sharing.kinds.get(type);
        if (kind == Kind.SHARED) {
            return original;
        }
        Object done = copies.get(original);
        if (done != null) {
            return done;
        }
        if (kind == Kind.ARRAY) {
            return copyArray(original, type);
        }
        if (kind == Kind.JDK) {
            return copyJdk(original, type);
        }
        Plan plan = PLANS.get(type);
        Object copy = Plan.allocate(type);
        copies.put(original, copy);
        try {
            for (Field f : plan.fields) {
                Class<?> t = f.getType();
                if (!t.isPrimitive()) {
                    f.set(copy, copyOf(f, original));
                } else if (t == double.class) {
                    f.setDouble(copy, f.getDouble(original));
                } else if (t == int.class) {
                    f.setInt(copy, f.getInt(original));
                } else if (t == long.class) {
                    f.setLong(copy, f.getLong(original));
                } else if (t == boolean.class) {
                    f.setBoolean(copy, f.getBoolean(original));
                } else {
                    f.set(copy, f.get(original)); // float, short, byte, char: boxed and unboxed exactly
                }
            }
        } catch (IllegalAccessException e) {
            throw new IllegalStateException("cannot checkpoint " + type.getName() + ": " + e.getMessage(), e);
        }
        return copy;
    }

    /** The copy of a field's value, naming the field if it cannot be copied: the path leads to what to change. */
    private Object copyOf(Field field, Object holder) throws IllegalAccessException {
        try {
            return copy(field.get(holder));
        } catch (IllegalStateException e) {
            throw new IllegalStateException(e.getMessage() + ", in " + field.getDeclaringClass().getSimpleName()
                    + "." + field.getName(), e.getCause());
        }
    }

    private static boolean isValue(Class<?> type) {
        return type.isPrimitive() || type.isEnum() || type == String.class || type == Class.class
                || Number.class.isAssignableFrom(type) && type.getName().startsWith("java.lang.")
                || type == Boolean.class || type == Character.class
                || type.getSuperclass() != null && type.getSuperclass().isEnum(); // an enum constant with a body
    }

    private boolean isShared(Object element) {
        return element == null || sharing.kinds.get(element.getClass()) == Kind.SHARED;
    }

    private Object copyArray(Object original, Class<?> type) {
        int n = Array.getLength(original);
        if (type.getComponentType().isPrimitive()) {
            Object copy = original instanceof double[] a ? a.clone()
                    : original instanceof int[] a ? a.clone()
                    : original instanceof long[] a ? a.clone()
                    : original instanceof boolean[] a ? a.clone()
                    : original instanceof float[] a ? a.clone()
                    : original instanceof byte[] a ? a.clone()
                    : original instanceof short[] a ? (Object) a.clone()
                    : ((char[]) original).clone();
            copies.put(original, copy);
            return copy;
        }
        Object[] from = (Object[]) original;
        Object[] copy = (Object[]) Array.newInstance(type.getComponentType(), n);
        copies.put(original, copy);
        for (int i = 0; i < n; i++) {
            copy[i] = copy(from[i]);
        }
        return copy;
    }

    @SuppressWarnings({"unchecked", "rawtypes"})
    private Object copyJdk(Object original, Class<?> type) {
        Object copy;
        if (type == ArrayList.class) {
            copy = fill(new ArrayList<>(((Collection<?>) original).size()), (Collection<?>) original);
        } else if (type == ArrayDeque.class) {
            copy = fill(new ArrayDeque<>(), (Collection<?>) original);
        } else if (type == PriorityQueue.class) {
            // the heap's array may be laid out differently, but it polls in the same order when the
            // elements are totally ordered, as scheduled events are (by tick, ordering, sequence)
            PriorityQueue<?> queue = (PriorityQueue<?>) original;
            copy = fill(new PriorityQueue(Math.max(1, queue.size()), queue.comparator()), queue);
        } else if (original instanceof EnumSet<?> set) {
            copy = set.clone();
        } else if (type == HashMap.class || type == LinkedHashMap.class || type == EnumMap.class) {
            Map<Object, Object> from = (Map<Object, Object>) original;
            Map<Object, Object> map = type == HashMap.class ? new HashMap<>()
                    : type == LinkedHashMap.class ? new LinkedHashMap<>() : new EnumMap((EnumMap) original);
            copies.put(original, map);
            for (Map.Entry<Object, Object> e : from.entrySet()) {
                map.put(copy(e.getKey()), copy(e.getValue()));
            }
            return map;
        } else if (type.getName().startsWith("java.util.ImmutableCollections$")) {
            Collection<?> from = original instanceof Map<?, ?> m ? m.values() : (Collection<?>) original;
            boolean values = true;
            for (Object element : from) {
                values &= isShared(element);
            }
            if (values) {
                return original; // nothing in it can change
            }
            if (!(original instanceof List<?> list)) {
                throw new IllegalStateException("cannot checkpoint an unmodifiable " + type.getSimpleName()
                        + " of the model's objects: hold a collection the model owns instead");
            }
            List<Object> elements = new ArrayList<>(list.size());
            for (Object element : list) {
                elements.add(copy(element));
            }
            copy = List.copyOf(elements);
        } else {
            throw new IllegalStateException("cannot checkpoint a " + type.getName()
                    + ": copy only the model's own classes, arrays and plain JDK collections");
        }
        copies.put(original, copy);
        return copy;
    }

    private <C extends Collection<Object>> C fill(C target, Collection<?> from) {
        copies.put(from, target);
        for (Object element : from) {
            target.add(copy(element));
        }
        return target;
    }

    /** How to copy one of the model's classes: every instance field, its own and its superclasses'. */
    private record Plan(Field[] fields) {
        private static final sun.misc.Unsafe UNSAFE = unsafe();

        /**
         * The plan for {@code type}, which must have no final instance field: writing one takes deep
         * reflection that JDK 26 warns about and later JDKs refuse (JEP 500), so the model keeps what
         * a checkpoint copies in fields that are not final.
         */
        static Plan of(Class<?> type) {
            List<Field> fields = instanceFields(type);
            for (Field f : fields) {
                if (Modifier.isFinal(f.getModifiers())) {
                    throw new IllegalStateException("cannot checkpoint " + type.getName() + ": its field "
                            + f.getDeclaringClass().getSimpleName() + "." + f.getName() + " is final, and a copy"
                            + " would have to write it; make the field non-final, or share its class if it never changes");
                }
                f.setAccessible(true);
            }
            return new Plan(fields.toArray(Field[]::new));
        }

        static List<Field> instanceFields(Class<?> type) {
            List<Field> fields = new ArrayList<>();
            // a JDK superclass's fields (an AbstractList's modification count) are its own bookkeeping
            for (Class<?> c = type; c != null && !c.getName().startsWith("java."); c = c.getSuperclass()) {
                for (Field f : c.getDeclaredFields()) {
                    if (!Modifier.isStatic(f.getModifiers())) {
                        fields.add(f);
                    }
                }
            }
            return fields;
        }

        /** An instance whose fields the copy then fills in: no constructor may run, as in deserialization. */
        static Object allocate(Class<?> type) {
            try {
                return UNSAFE.allocateInstance(type);
            } catch (InstantiationException e) {
                throw new IllegalStateException("cannot checkpoint " + type.getName() + ": " + e.getMessage(), e);
            }
        }

        private static sun.misc.Unsafe unsafe() {
            try {
                Field f = sun.misc.Unsafe.class.getDeclaredField("theUnsafe");
                f.setAccessible(true);
                return (sun.misc.Unsafe) f.get(null);
            } catch (ReflectiveOperationException e) {
                throw new ExceptionInInitializerError(e);
            }
        }
    }
}
