/**
 * The MASON-style simulation kernel: a {@link sitcov.engine.Schedule} of {@link sitcov.engine.Steppable}
 * agents keyed by tick and ordering, the {@link sitcov.engine.SimState} that owns it, and the
 * {@link sitcov.engine.RandomStreams} every random choice comes from. Depends on nothing else in sitcov.
 */
package sitcov.engine;
