;;; sled-mode.el --- Major mode for sled crash-victim scenarios  -*- lexical-binding: t; -*-

;; A small major mode for .sled files: comments, indentation by braces, font-lock of keywords,
;; numbers, units and strings; and `sled lsp' registered with eglot (Emacs 29 and later) for
;; diagnostics, hover, completion, definitions, references, formatting and quick fixes.
;; See docs/editors.md.
;;
;;   (add-to-list 'load-path "/path/to/sled/editors/emacs")
;;   (require 'sled-mode)
;;   (add-hook 'sled-mode-hook #'eglot-ensure)

;;; Code:

(defgroup sled nil
  "Editing sled scenarios."
  :group 'languages)

(defcustom sled-program "sled"
  "The sled program that `sled lsp' is run from."
  :type 'string
  :group 'sled)

(defcustom sled-indent-offset 2
  "Indentation of a block's statements, as `sled fmt' writes them."
  :type 'integer
  :group 'sled)

(defconst sled--declarations
  '("scenario" "import" "param" "let" "body" "segment" "joint" "vehicle" "plane" "ellipsoid"
    "function" "contact" "belt" "harness" "airbag" "spring" "tension" "constraint" "load" "initial"
    "override" "output" "time" "integrator" "restart" "settle" "symmetry" "wind" "water"
    "actuator"))

(defconst sled--font-lock-keywords
  `((,(concat "^[ \t]*" (regexp-opt sled--declarations 'words)
              "\\(?:[ \t]+\\([A-Za-z_][A-Za-z0-9_.]*\\)\\)?")
     (1 font-lock-keyword-face)
     (2 font-lock-variable-name-face nil t))
    (,(regexp-opt '("on" "with" "at" "as" "filter") 'words) . font-lock-builtin-face)
    (,(regexp-opt '("true" "false") 'words) . font-lock-constant-face)
    ;; A number and the unit written after it (`56 km/h`, `2.5 N*m/deg`).
    ("\\_<\\([0-9]+\\(?:\\.[0-9]*\\)?\\(?:[eE][+-]?[0-9]+\\)?\\)\\(?:[ \t]*\\([A-Za-z_][A-Za-z0-9_]*\\(?:\\^-?[0-9]+\\)?\\(?:[*/][A-Za-z_][A-Za-z0-9_]*\\(?:\\^-?[0-9]+\\)?\\)*\\)\\_>\\(?:[ \t]*[=.(:]\\)\\@!\\)?"
     (1 font-lock-constant-face)
     (2 font-lock-type-face nil t))
    ;; The unit of a vector: `(0, 0, -9.81) m/s^2'.
    (")[ \t]*\\([A-Za-z_][A-Za-z0-9_]*\\(?:\\^-?[0-9]+\\)?\\(?:[*/][A-Za-z_][A-Za-z0-9_]*\\(?:\\^-?[0-9]+\\)?\\)*\\)"
     (1 font-lock-type-face))
    ("\\_<\\([A-Za-z_][A-Za-z0-9_.]*\\)(" (1 font-lock-function-name-face))
    ("\\_<\\([A-Za-z_][A-Za-z0-9_]*\\)[ \t]*=[^=]" (1 font-lock-variable-name-face))))

(defvar sled-mode-syntax-table
  (let ((table (make-syntax-table)))
    (modify-syntax-entry ?/ ". 12" table)
    (modify-syntax-entry ?\n ">" table)
    (modify-syntax-entry ?_ "_" table)
    (modify-syntax-entry ?. "_" table)
    (modify-syntax-entry ?\" "\"" table)
    table)
  "Syntax table of `sled-mode': `//' comments, strings, names with `_' and `.'.")

(defun sled-indent-line ()
  "Indent the current line by the braces open before it."
  (interactive)
  (let* ((depth (save-excursion (car (syntax-ppss (line-beginning-position)))))
         (closing (save-excursion (back-to-indentation) (eq (char-after) ?})))
         (column (* sled-indent-offset (max 0 (- depth (if closing 1 0))))))
    (if (<= (current-column) (current-indentation))
        (indent-line-to column)
      (save-excursion (indent-line-to column)))))

;;;###autoload
(define-derived-mode sled-mode prog-mode "sled"
  "Major mode for sled scenarios (.sled files)."
  :syntax-table sled-mode-syntax-table
  (setq-local comment-start "// ")
  (setq-local comment-start-skip "//+[ \t]*")
  (setq-local font-lock-defaults '(sled--font-lock-keywords))
  (setq-local indent-line-function #'sled-indent-line))

;;;###autoload
(add-to-list 'auto-mode-alist '("\\.sled\\'" . sled-mode))

(with-eval-after-load 'eglot
  (add-to-list 'eglot-server-programs
               `(sled-mode . ,(lambda (&rest _) (list sled-program "lsp")))))

(provide 'sled-mode)
;;; sled-mode.el ends here
