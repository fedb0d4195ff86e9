/**
 * The MASON-style simulation kernel: a {@link sitcov.engine.Schedule} of {@link sitcov.engine.Steppable}
 * agents keyed by tick and ordering, the {@link sitcov.engine.SimState} that owns it, and the
 * {@link sitcov.engine.RandomStreams} every random choice comes from (SplitMix64, {@link sitcov.engine.SplitMix}),
 * and {@link sitcov.engine.ModelCopy}, the deep copy a checkpoint of a run is. Depends on nothing else in sitcov.
 *
 * <p>The schedule, its events and the random streams keep no final instance fields, nor does any
 * other class whose objects a checkpoint copies: a copy writes every field, and reflection may not
 * write a final one.
 */
package sitcov.engine;
