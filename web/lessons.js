'use strict';
// Lessons: the desktop's lesson files (datasets/lessons/, gui/models/lessons.h), read by the
// desktop's reader inside the module. A lesson's narrative and each step's caption show
// above the views; applying a step sets its state (a window state object), goes to its
// frame and plays its frames. The claims are listed as the sentences they check; the
// desktop checks them (`oflab --check-lesson`), the page does not.

function loadLessons() {
  const lessons = JSON.parse(Module.Session.lessonsJson());
  if (lessons.error) {
    showMessage(`The shipped lessons could not be read: ${lessons.error}`);
    app.lessons = [];
  } else {
    app.lessons = lessons;
  }
  fillLessonPicker();
}

function fillLessonPicker() {
  const picker = $('lesson');
  while (picker.options.length > 1) picker.remove(1);
  for (const lesson of app.lessons) picker.add(new Option(lesson.title, lesson.name));
  picker.value = app.lesson ? app.lesson.name : '';
}

function startLesson(name) {
  app.lesson = app.lessons.find((l) => l.name === name) || null;
  $('lesson').value = app.lesson ? app.lesson.name : '';
  $('lesson-panel').hidden = !app.lesson;
  if (!app.lesson) {
    showMessage(name ? `There is no lesson '${name}' (lessons: ${app.lessons.map((l) => l.name).join(', ')})` : '');
    return;
  }
  showLessonStep(0);
}

// The lesson's narrative (step 0) or its k-th step: the state of that step (a step without
// a state keeps the one before), its frame, then its frames played.
function showLessonStep(k) {
  const lesson = app.lesson;
  if (!lesson) return;
  k = Math.max(0, Math.min(lesson.steps.length, k));
  app.lessonStep = k;
  let state = lesson.state;
  for (let i = 0; i < k; ++i) if (lesson.steps[i].state) state = lesson.steps[i].state;
  const step = k > 0 ? lesson.steps[k - 1] : null;
  const shown = JSON.parse(JSON.stringify(state));
  shown.lesson_step = k;
  if (!applyState(shown, `lessons/${lesson.name}.json`)) return;
  showMessage('');
  const play = step ? step.play : lesson.play;
  const from = step && step.frame >= 0 ? step.frame : app.state.frame;
  seek(from + play);
  setPlaying(false);
  $('lesson-title').textContent = lesson.title;
  $('lesson-caption').textContent = step ? step.say : lesson.narrative;
  $('lesson-step').textContent = k > 0 ? `step ${k} of ${lesson.steps.length}` : `narrative (${lesson.steps.length} steps)`;
  const claims = step ? step.claims : [];
  $('lesson-claims').innerHTML = claims.map((c) => `<li>checks: ${escapeHtml(c)}</li>`).join('');
  $('lesson-prev').disabled = k === 0;
  $('lesson-next').disabled = k === lesson.steps.length;
}

function escapeHtml(text) {
  return text.replace(/[&<>"]/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;' }[c]));
}
