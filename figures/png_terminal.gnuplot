# The PNG terminal of a figure (loaded after the script sets `width`, `height`, `fontsize`): the
# full size for build/figures/, or 800 pixels wide with fonts scaled alike (not below 8 points)
# when small=1, for the reference figures of docs/figures/ (`make docs-figures`).
if (exists("small") && small) { scale = 800.0/width } else { scale = 1.0 }
set terminal pngcairo size int(width*scale), int(height*scale) \
    font sprintf("Sans,%g", (fontsize*scale < 8 ? 8 : fontsize*scale)) noenhanced
