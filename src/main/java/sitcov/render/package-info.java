/**
 * Pictures of maps and runs, drawn with Java2D (headless): a map ({@link sitcov.render.MapRenderer}, its
 * legend, shapes, style and caption; labels kept apart by {@link sitcov.render.LabelPlacer}), a run over
 * it ({@link sitcov.render.RunRenderer}, from what a {@link sitcov.render.TrajectoryRecorder} saw), a run
 * and its faulty twin side by side ({@link sitcov.render.ReplayPicture}) or animated as a GIF
 * ({@link sitcov.render.ReplayAnimation}, {@link sitcov.render.GifFrames}), a results folder's pictures of
 * its failures and findings ({@link sitcov.render.ReplayGallery}) and a gallery of runs that went
 * wrong ({@link sitcov.render.RunGallery}); and a run's per-tick trace as CSV
 * ({@link sitcov.render.TraceWriter}). Near misses are put into words once ({@link sitcov.render.NearMissText})
 * and watched beside a recorded run ({@link sitcov.render.NearMissWatch}) for the tick each least was reached.
 */
package sitcov.render;
